#include "vrlis_integration/effort_price.hpp"

#include <algorithm>
#include <cmath>

namespace vrlis::integration {

EffortPrice::EffortPrice(int width, int height)
    : width_(width),
      height_(height),
      sum_(static_cast<std::size_t>(width) * height),
      sum_sq_(sum_.size()) {}

void EffortPrice::Add(const Film& pass, double pixel_seconds, const EffortStats& medium, const EffortStats& surface) {
  for (std::size_t i = 0; i < sum_.size(); ++i) {
    const Spectrum& s = pass.pixels[i];
    double v = std::sqrt((double(s.r) * s.r + double(s.g) * s.g + double(s.b) * s.b) / 3);
    if (!std::isfinite(v)) continue;
    sum_[i] += v;
    sum_sq_[i] += v * v;
  }
  pixel_seconds_ += pixel_seconds;
  const EffortStats* stats[2] = {&medium, &surface};
  for (int kind = 0; kind < 2; ++kind) {
    gathers_[kind] += *stats[kind];
    if (price_[kind] == 0) uncontrolled_[kind] += *stats[kind];  // this pass took every gather once
  }
  ++passes_;
  if (passes_ >= kMinPasses) Refresh();
}

void EffortPrice::Refresh() {
  const double n = passes_;
  // The mean over pixels of their variance, the largest thousandth left out.
  std::vector<double> pixels(sum_.size());
  for (std::size_t i = 0; i < sum_.size(); ++i) {
    double mean = sum_[i] / n;
    pixels[i] = std::max(0.0, (sum_sq_[i] - n * mean * mean) / (n - 1));
  }
  const std::size_t kept = pixels.size() - pixels.size() / 1000;
  std::nth_element(pixels.begin(), pixels.begin() + static_cast<std::ptrdiff_t>(kept) - 1, pixels.end());
  double variance = 0;
  for (std::size_t k = 0; k < kept; ++k) variance += pixels[k];
  variance /= double(kept);
  const double pixel_cost = pixel_seconds_ / (n * double(sum_.size()));
  for (int kind = 0; kind < 2; ++kind) {
    const EffortStats& g = gathers_[kind];
    const EffortStats& u = uncontrolled_[kind];
    const double gather_cost = u.gathers > 0 ? u.seconds / double(u.gathers) : 0;
    const double calibration = g.predicted > 0 ? g.measured / g.predicted : 0;
    price_[kind] = variance > 0 && gather_cost > 0 && calibration > 0
                       ? calibration * pixel_cost / (variance * gather_cost)
                       : 0;
  }
}

}  // namespace vrlis::integration
