// The equal-time study's efficiency ratio (bench/compare/efficiency.hpp): exact on
// replicates whose ratio is known, what a user gets where replicates differ, and intervals
// that cover the true ratio about as often as they claim.
#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "efficiency.hpp"

using vrlis::compare::EfficiencyRatio;
using vrlis::compare::Replicates;

TEST_CASE("a sampler's ratio to itself is one, to one at twice the time two", "[compare]") {
  Replicates a{{1.0, 1.3, 0.8, 1.1}, {2.0, 2.1, 1.9, 2.0}}, slow = a;
  for (double& s : slow.seconds) s *= 2;
  const auto same = EfficiencyRatio(a, a), twice = EfficiencyRatio(a, slow);
  CHECK(same.point == Approx(1).epsilon(1e-12));
  CHECK(twice.point == Approx(2).epsilon(1e-12));
  CHECK(twice.low == Approx(2).epsilon(1e-12));  // paired replicates of one shape: no spread
}

TEST_CASE("replicates of equal efficiency that differ in variance and time are as efficient as each", "[compare]") {
  // A method whose replicates take different models: half at k times the variance and 1 / k
  // of the time, half the other way. Each image's squared error at equal time is the same,
  // so the method is as efficient as a method of one model; pooling the variances and the
  // times apart would make it 4 / (2 + k + 1 / k) of that (0.64 at k = 4).
  const double k = 4;
  Replicates one, split;
  for (int r = 0; r < 12; ++r) {
    one.variance.push_back(1), one.seconds.push_back(1);
    split.variance.push_back(r % 2 ? k : 1 / k), split.seconds.push_back(r % 2 ? 1 / k : k);
  }
  CHECK(EfficiencyRatio(split, one).point == Approx(1).epsilon(1e-12));
  CHECK(vrlis::compare::Efficiency(split) == Approx(1).epsilon(1e-12));
}

TEST_CASE("the interval covers the true ratio about as often as it claims", "[compare]") {
  // Paired replicates as the study's: a shared factor (the light paths both samplers see) and
  // each sampler's own noise in the variance, a little in the time; b is half as efficient.
  std::mt19937_64 rng(12);
  std::normal_distribution<double> normal;
  const int trials = 2000;
  int covered = 0, separated = 0;
  for (int t = 0; t < trials; ++t) {
    Replicates a, b;
    for (int r = 0; r < 12; ++r) {
      const double shared = std::exp(0.5 * normal(rng));
      a.variance.push_back(shared * std::exp(0.3 * normal(rng))), a.seconds.push_back(std::exp(0.05 * normal(rng)));
      b.variance.push_back(2 * shared * std::exp(0.3 * normal(rng))), b.seconds.push_back(std::exp(0.05 * normal(rng)));
    }
    const auto ratio = EfficiencyRatio(a, b);
    if (ratio.low <= 2 && 2 <= ratio.high) ++covered;
    if (ratio.Above(1)) ++separated;
  }
  const double coverage = double(covered) / trials;
  INFO("coverage " << coverage << ", separated from 1 in " << separated << " of " << trials);
  CHECK(coverage > 0.90);
  CHECK(coverage < 0.99);
  CHECK(separated > 0.9 * trials);
}
