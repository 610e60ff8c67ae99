#pragma once
// A discrete distribution sampled in constant time (Walker's alias method, built by Vose's
// algorithm): each of n cells holds one item with probability `keep` and an alias for the
// rest, so a sample is one cell index and one comparison. A binary search over a CDF, the
// alternative, mispredicts about half of its log2(n) branches per sample.
#include <cstdint>
#include <vector>

namespace vrlis::integration {

class AliasTable {
 public:
  AliasTable() = default;
  // weights: non-negative, finite; items of weight zero are never sampled. An empty table
  // (no positive weight) samples nothing.
  explicit AliasTable(const std::vector<double>& weights);

  bool empty() const { return cells_.empty(); }
  struct Pick {
    std::uint32_t index;
    float probability;  // of choosing `index`
  };
  // The item (its index among the weights) for the uniform u in [0, 1): n u's integer part
  // picks a cell, its fraction the cell's own item or its alias.
  Pick Sample(float u) const {
    // In double: n u stays below n for every float u < 1.
    const double scaled = double(u) * double(cells_.size());
    const std::size_t c = std::size_t(scaled);
    const Cell& cell = cells_[c < cells_.size() ? c : cells_.size() - 1];
    return scaled - double(c) < double(cell.keep) ? Pick{cell.item, cell.probability}
                                                  : Pick{cell.alias, cell.alias_probability};
  }

 private:
  struct Cell {
    float keep;  // the probability of the cell's own item, given the cell
    std::uint32_t item, alias;
    float probability, alias_probability;  // of choosing each
  };
  std::vector<Cell> cells_;
};

}  // namespace vrlis::integration
