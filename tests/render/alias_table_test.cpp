// The VPLs' choice by flux (AliasTable): samples follow the weights (Pearson's chi-square,
// zero weights never sampled), each pick reports its own probability, and the same test
// rejects a sampler that ignores the cells' split between item and alias.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <vrlis_integration/alias_table.hpp>

#include "stats.hpp"  // tests/support: Pearson's chi-square

namespace {

using vrlis::integration::AliasTable;

// Weights spanning three decades, zeros among them, and one item of half the total.
std::vector<double> Weights() {
  std::vector<double> w;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> decades(-3, 0);
  for (int i = 0; i < 40; ++i) w.push_back(i % 9 == 4 ? 0.0 : std::pow(10.0, decades(rng)));
  double total = 0;
  for (double x : w) total += x;
  w[17] = total;
  return w;
}

// Counts of n picks; `sample` maps u to an item index.
template <typename Sample>
std::vector<long> Counts(std::size_t items, long n, Sample sample) {
  std::vector<long> counts(items, 0);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (long k = 0; k < n; ++k) ++counts.at(sample(uniform(rng)));
  return counts;
}

}  // namespace

TEST_CASE("an alias table samples its weights and reports each pick's probability", "[render][vpl]") {
  const std::vector<double> w = Weights();
  double total = 0;
  for (double x : w) total += x;
  const AliasTable table(w);
  const long n = 400000;
  long wrong_probability = 0;
  const auto counts = Counts(w.size(), n, [&](float u) {
    const AliasTable::Pick pick = table.Sample(u);
    wrong_probability += std::abs(pick.probability / (w[pick.index] / total) - 1) > 1e-6;
    return pick.index;
  });
  CHECK(wrong_probability == 0);
  const auto chi = vrlis::test::PearsonTest(counts, w, n);
  INFO("chi-square " << chi.statistic << " on " << chi.dof << " dof, p = " << chi.p_value);
  CHECK(chi.Passes());
  CHECK(table.Sample(std::nextafter(1.0f, 0.0f)).probability > 0);

  // Sabotage: every cell's own item, its alias never taken.
  std::size_t cells = 0;  // the table's: one per positive weight
  for (double x : w) cells += x > 0;
  const auto own = Counts(w.size(), n, [&](float u) {
    const auto cell = std::size_t(double(u) * double(cells));
    std::size_t seen = 0;
    for (std::size_t i = 0; i < w.size(); ++i)
      if (w[i] > 0 && seen++ == cell) return i;
    return w.size() - 1;
  });
  CHECK_FALSE(vrlis::test::PearsonTest(own, w, n).Passes());
}

TEST_CASE("an alias table of no positive weight is empty", "[render][vpl]") {
  CHECK(AliasTable(std::vector<double>{}).empty());
  CHECK(AliasTable({0.0, 0.0}).empty());
  CHECK_FALSE(AliasTable({0.0, 1.0}).empty());
  CHECK(AliasTable({0.0, 1.0}).Sample(0.3f).index == 1);
}
