#include "vrlis_integration/alias_table.hpp"

#include <cmath>

namespace vrlis::integration {

AliasTable::AliasTable(const std::vector<double>& weights) {
  double total = 0;
  std::vector<std::uint32_t> items;
  for (std::size_t i = 0; i < weights.size(); ++i)
    if (weights[i] > 0 && std::isfinite(weights[i])) total += weights[i], items.push_back(std::uint32_t(i));
  if (items.empty()) return;
  const std::size_t n = items.size();
  // Each cell's share of n: above 1 it lends to cells below 1 until it is 1 itself (Vose).
  std::vector<double> share(n);
  std::vector<std::uint32_t> small, large;
  cells_.resize(n);
  for (std::size_t c = 0; c < n; ++c) {
    const double p = weights[items[c]] / total;
    cells_[c] = {1, items[c], items[c], float(p), float(p)};
    share[c] = p * double(n);
    (share[c] < 1 ? small : large).push_back(std::uint32_t(c));
  }
  while (!small.empty() && !large.empty()) {
    const std::uint32_t s = small.back(), l = large.back();
    small.pop_back();
    cells_[s].keep = float(share[s]);
    cells_[s].alias = cells_[l].item;
    cells_[s].alias_probability = cells_[l].probability;
    share[l] -= 1 - share[s];
    if (share[l] < 1) large.pop_back(), small.push_back(l);
  }
  // What is left holds share 1 up to rounding: it keeps its own item (keep = 1 from above).
}

}  // namespace vrlis::integration
