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
  gathers_[0] += medium;
  gathers_[1] += surface;
  ++passes_;
  if (passes_ >= kMinPasses) Refresh();
}

void EffortPrice::Refresh() {
  const double n = passes_;
  // Per 8 x 8 tile the mean variance of its pixels, the largest tenth left out; their mean.
  std::vector<double> pixels;
  double variance = 0;
  int tiles = 0;
  for (int ty = 0; ty < height_; ty += kTile)
    for (int tx = 0; tx < width_; tx += kTile) {
      pixels.clear();
      for (int y = ty; y < std::min(height_, ty + kTile); ++y)
        for (int x = tx; x < std::min(width_, tx + kTile); ++x) {
          std::size_t i = static_cast<std::size_t>(y) * width_ + x;
          double mean = sum_[i] / n;
          pixels.push_back(std::max(0.0, (sum_sq_[i] - n * mean * mean) / (n - 1)));
        }
      std::sort(pixels.begin(), pixels.end());
      std::size_t kept = pixels.size() - pixels.size() / 10;
      double tile = 0;
      for (std::size_t k = 0; k < kept; ++k) tile += pixels[k];
      variance += tile / kept;
      ++tiles;
    }
  variance /= tiles;
  const double pixel_cost = pixel_seconds_ / (n * sum_.size());
  for (int kind = 0; kind < 2; ++kind) {
    const EffortStats& g = gathers_[kind];
    const double gather_cost = g.gathers > 0 ? g.seconds / double(g.gathers) : 0;
    const double calibration = g.predicted > 0 ? g.measured / g.predicted : 0;
    price_[kind] = variance > 0 && gather_cost > 0 && calibration > 0
                       ? calibration * pixel_cost / (variance * gather_cost)
                       : 0;
  }
}

}  // namespace vrlis::integration
