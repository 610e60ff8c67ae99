// vrlis::RunningMoments against a two-pass computation in long double, on heavy-tailed
// weights shifted far from zero (where the one-pass sum of squares cancels: the control
// shows the comparison can tell the two apart); merge() against one sequential stream;
// and the variance of the mean as the width of a z-test that accepts the true mean and
// rejects a wrong one.
#include <catch2/catch.hpp>

#include <vrlis/core/running_moments.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

namespace {

// Pareto weights with tail index 1.5 (finite mean, infinite variance: the worst case the
// study's f / pdf meets), scaled and shifted.
std::vector<double> HeavyTailed(std::uint64_t seed, std::size_t n, double shift) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  std::vector<double> x(n);
  for (double& v : x) v = shift + 1e-3 * std::pow(1 - uniform(rng), -1 / 1.5);
  return x;
}

struct Exact {
  long double mean = 0, variance = 0, max = -std::numeric_limits<long double>::infinity();
};

// Two passes: the mean first, then the squared deviations from it.
Exact TwoPass(const std::vector<double>& x) {
  Exact e;
  for (double v : x) e.mean += v;
  e.mean /= static_cast<long double>(x.size());
  for (double v : x) {
    e.variance += (v - e.mean) * (v - e.mean);
    if (v > e.max) e.max = v;
  }
  e.variance /= static_cast<long double>(x.size() - 1);
  return e;
}

double RelativeError(double value, long double exact) {
  return static_cast<double>(std::abs((static_cast<long double>(value) - exact) / exact));
}

}  // namespace

TEST_CASE("RunningMoments matches a two-pass computation on shifted heavy-tailed weights", "[lib][moments]") {
  for (double shift : {0.0, 1.0, 1e3}) {
    const std::vector<double> x = HeavyTailed(7, 200000, shift);
    const Exact exact = TwoPass(x);
    vrlis::RunningMoments m;
    double sum = 0, sum_sq = 0;  // the one-pass textbook formula, as the control
    for (double v : x) {
      m.add(v);
      sum += v;
      sum_sq += v * v;
    }
    const double n = static_cast<double>(x.size());
    const double textbook = (sum_sq - sum * sum / n) / (n - 1);
    INFO("shift " << shift << ": variance " << m.variance() << ", two-pass " << static_cast<double>(exact.variance)
                  << ", textbook " << textbook);
    CHECK(m.count() == static_cast<std::int64_t>(x.size()));
    CHECK(RelativeError(m.mean(), exact.mean) < 1e-12);  // the running mean rounds ~sqrt(n) eps (measured 3e-14)
    CHECK(RelativeError(m.variance(), exact.variance) < 1e-10);
    CHECK(RelativeError(m.variance_of_mean(), exact.variance / x.size()) < 1e-10);
    CHECK(static_cast<long double>(m.max()) == exact.max);
    // A mean 1e3 times the spread costs the textbook formula six digits (Welford keeps
    // eleven): the tolerance above tells the two apart.
    if (shift >= 1e3) CHECK(RelativeError(textbook, exact.variance) > 1e-6);
  }
}

TEST_CASE("RunningMoments: merging partial streams equals one sequential stream", "[lib][moments]") {
  const std::vector<double> x = HeavyTailed(11, 30001, 3.0);
  vrlis::RunningMoments sequential;
  for (double v : x) sequential.add(v);
  for (std::size_t split : {std::size_t(0), std::size_t(1), std::size_t(2), std::size_t(12345), x.size() - 1, x.size()}) {
    vrlis::RunningMoments a, b;
    for (std::size_t i = 0; i < x.size(); ++i) (i < split ? a : b).add(x[i]);
    a.merge(b);
    INFO("split at " << split);
    CHECK(a.count() == sequential.count());
    CHECK(a.mean() == Approx(sequential.mean()).epsilon(1e-13));
    CHECK(a.variance() == Approx(sequential.variance()).epsilon(1e-11));
    CHECK(a.max() == sequential.max());
  }
  // Many small pieces merged in a tree, as per-thread partial sums are.
  std::vector<vrlis::RunningMoments> pieces(64);
  for (std::size_t i = 0; i < x.size(); ++i) pieces[i * pieces.size() / x.size()].add(x[i]);
  for (std::size_t width = 1; width < pieces.size(); width *= 2)
    for (std::size_t i = 0; i + width < pieces.size(); i += 2 * width) pieces[i].merge(pieces[i + width]);
  CHECK(pieces[0].count() == sequential.count());
  CHECK(pieces[0].mean() == Approx(sequential.mean()).epsilon(1e-13));
  CHECK(pieces[0].variance() == Approx(sequential.variance()).epsilon(1e-11));
}

TEST_CASE("RunningMoments: the standard error accepts the true mean and rejects a wrong one", "[lib][moments]") {
  // Exponential weights with mean 1 and variance 1: the standard error is 1 / sqrt(n).
  std::mt19937_64 rng(5);
  std::exponential_distribution<double> exponential(1.0);
  vrlis::RunningMoments m;
  const int n = 100000;
  for (int i = 0; i < n; ++i) m.add(exponential(rng));
  INFO("mean " << m.mean() << " standard error " << m.standard_error());
  CHECK(m.variance() == Approx(1).epsilon(0.05));
  CHECK(m.standard_error() == Approx(1 / std::sqrt(double(n))).epsilon(0.05));
  CHECK(std::abs(m.mean() - 1) < 4.5 * m.standard_error());
  CHECK(std::abs(m.mean() - 1.05) > 4.5 * m.standard_error());
}

TEST_CASE("RunningMoments: empty and single-value accumulators", "[lib][moments]") {
  vrlis::RunningMoments m;
  CHECK(m.count() == 0);
  CHECK(m.mean() == 0);
  CHECK(m.variance() == 0);
  CHECK(m.variance_of_mean() == 0);
  CHECK(m.max() == -std::numeric_limits<double>::infinity());
  vrlis::RunningMoments empty;
  m.merge(empty);
  CHECK(m.count() == 0);
  m.add(-2.5);
  CHECK(m.mean() == -2.5);
  CHECK(m.variance() == 0);
  CHECK(m.max() == -2.5);
  empty.merge(m);
  CHECK(empty.count() == 1);
  CHECK(empty.mean() == -2.5);
}
