#pragma once
// The image-level price of variance behind the effort control (docs/maths.md#effort), learned
// from the passes already rendered: the variance of one pass's pixel estimate, averaged over
// pixels with the largest thousandth left out (a few fireflies must not flip decisions; the
// predicted second moments keep theirs, and more left out here overprices variance), and the
// time a pixel and a gather cost. A pass's decisions read the price of the passes
// before it only: the renderer adds a pass after rendering it.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "film.hpp"

namespace vrlis::integration {

// What a pass's gathers tell the price, summed over pixels: the gathers taken, their time,
// the predicted second moments (vrlis::EffortTally) and the samples' own estimate of them.
// Of the gathers split into several samples: the sum of their within variances and of their
// second moments, each estimated from its own samples (the share splitting reduces).
struct EffortStats {
  std::uint64_t gathers = 0;
  double seconds = 0, predicted = 0, measured = 0;
  double split_within = 0, split_second = 0;
  void operator+=(const EffortStats& o) {
    gathers += o.gathers, seconds += o.seconds, predicted += o.predicted, measured += o.measured;
    split_within += o.split_within, split_second += o.split_second;
  }
};

// The two gathers, each with its own calibration and cost: their bounds are not equally tight.
enum class GatherKind { Medium, Surface };

class EffortPrice {
 public:
  static constexpr int kMinPasses = 2;  // a variance needs two passes

  EffortPrice() = default;
  EffortPrice(int width, int height);
  // One finished pass: its image, the seconds its pixels took (summed over threads) and
  // what its medium-to-medium and medium-to-surface gathers tell.
  void Add(const Film& pass, double pixel_seconds, const EffortStats& medium, const EffortStats& surface);
  // The price of a gather: (pixel cost / pixel variance) / gather cost x (measured / predicted
  // second moments), in 1 / (predicted second moment); 0 before kMinPasses passes (every
  // gather taken once).
  double price(GatherKind kind) const { return price_[static_cast<int>(kind)]; }
  // The within share of the split gathers' second moments (vrlis::EffortSettings::within); 1
  // before any gather was split.
  double within(GatherKind kind) const {
    const EffortStats& g = gathers_[static_cast<int>(kind)];
    return g.split_second > 0 ? std::min(1.0, g.split_within / g.split_second) : 1;
  }
  int passes() const { return passes_; }

 private:
  void Refresh();

  int width_ = 0, height_ = 0, passes_ = 0;
  std::vector<double> sum_, sum_sq_;  // per pixel, of one pass's RMS RGB value
  double pixel_seconds_ = 0;
  EffortStats gathers_[2];
  EffortStats uncontrolled_[2];  // of the passes that took every gather once: the cost of one
  double price_[2] = {0, 0};
};

}  // namespace vrlis::integration
