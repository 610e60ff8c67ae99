#include "vrlis_integration/effort_price.hpp"

#include <algorithm>
#include <cmath>

namespace vrli {

EffortPrice::EffortPrice(int width, int height)
    : width_(width),
      height_(height),
      tiles_x_((width + kTile - 1) / kTile),
      tiles_y_((height + kTile - 1) / kTile),
      sum_(static_cast<std::size_t>(width) * height),
      sum_sq_(sum_.size()) {}

void EffortPrice::Add(const Film& pass, double pixel_seconds, const EffortStats& gathers) {
  for (std::size_t i = 0; i < sum_.size(); ++i) {
    const Spectrum& s = pass.pixels[i];
    double v = std::sqrt((double(s.r) * s.r + double(s.g) * s.g + double(s.b) * s.b) / 3);
    if (!std::isfinite(v)) continue;
    sum_[i] += v;
    sum_sq_[i] += v * v;
  }
  pixel_seconds_ += pixel_seconds;
  gathers_ += gathers;
  ++passes_;
  if (passes_ >= kMinPasses) Refresh();
}

void EffortPrice::Refresh() {
  const double n = passes_;
  std::vector<double> tile_variance(static_cast<std::size_t>(tiles_x_) * tiles_y_),
      tile_square(tile_variance.size());
  std::vector<std::pair<double, double>> pixels;  // (variance, mean square) of the tile's pixels
  for (int ty = 0; ty < tiles_y_; ++ty)
    for (int tx = 0; tx < tiles_x_; ++tx) {
      pixels.clear();
      for (int y = ty * kTile; y < std::min(height_, (ty + 1) * kTile); ++y)
        for (int x = tx * kTile; x < std::min(width_, (tx + 1) * kTile); ++x) {
          std::size_t i = static_cast<std::size_t>(y) * width_ + x;
          double mean = sum_[i] / n;
          pixels.push_back({std::max(0.0, (sum_sq_[i] - n * mean * mean) / (n - 1)), mean * mean});
        }
      std::sort(pixels.begin(), pixels.end());
      std::size_t kept = pixels.size() - pixels.size() / 10;  // the largest tenth left out
      double variance = 0, square = 0;
      for (std::size_t k = 0; k < kept; ++k) variance += pixels[k].first, square += pixels[k].second;
      std::size_t t = static_cast<std::size_t>(ty) * tiles_x_ + tx;
      tile_variance[t] = variance / kept;
      tile_square[t] = square / kept;
    }
  // Relative variance, so that dark tiles count as much as bright ones (EARS); a floor on the
  // mean square keeps black tiles finite.
  double mean_square = 0;
  for (double s : tile_square) mean_square += s;
  const double epsilon = 1e-4 * mean_square / tile_square.size() + 1e-30;
  double relative_variance = 0;
  for (std::size_t t = 0; t < tile_variance.size(); ++t) relative_variance += tile_variance[t] / (tile_square[t] + epsilon);
  relative_variance /= tile_variance.size();
  const double pixel_cost = pixel_seconds_ / (n * sum_.size());
  const double gather_cost = gathers_.gathers > 0 ? gathers_.seconds / double(gathers_.gathers) : 0;
  const double calibration = gathers_.predicted > 0 ? gathers_.measured / gathers_.predicted : 0;
  price_.assign(tile_variance.size(), 0);
  if (!(relative_variance > 0) || !(gather_cost > 0) || !(calibration > 0)) return;
  for (std::size_t t = 0; t < price_.size(); ++t)
    price_[t] = calibration * pixel_cost / relative_variance / (gather_cost * (tile_square[t] + epsilon));
}

}  // namespace vrli
