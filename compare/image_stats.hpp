#pragma once
// Per-pixel running sums of passes: the mean image, and the variance of that mean (for the
// reference, whose own noise is subtracted from every method's squared error).
#include <cstddef>
#include <vector>

#include <vrlis_integration/film.hpp>

namespace vrl_compare {

class PassStatistics {
 public:
  PassStatistics(int width, int height)
      : width_(width), height_(height), sum_(Size()), sum_sq_(Size()) {}

  void Add(const vrli::Film& pass) {
    for (std::size_t i = 0; i < pass.pixels.size(); ++i) {
      const vrli::Spectrum& s = pass.pixels[i];
      for (int c = 0; c < 3; ++c) {
        double v = c == 0 ? s.r : c == 1 ? s.g : s.b;
        sum_[3 * i + c] += v;
        sum_sq_[3 * i + c] += v * v;
      }
    }
    ++passes_;
  }

  int passes() const { return passes_; }
  int width() const { return width_; }
  int height() const { return height_; }

  std::vector<double> Mean() const {
    std::vector<double> m(sum_.size());
    for (std::size_t i = 0; i < m.size(); ++i) m[i] = sum_[i] / passes_;
    return m;
  }

  // Unbiased variance of the mean, per pixel and channel.
  std::vector<double> VarianceOfMean() const {
    std::vector<double> v(sum_.size());
    if (passes_ < 2) return v;
    for (std::size_t i = 0; i < v.size(); ++i) {
      double mean = sum_[i] / passes_;
      v[i] = (sum_sq_[i] / passes_ - mean * mean) * passes_ / (passes_ - 1.0) / passes_;
      if (v[i] < 0) v[i] = 0;
    }
    return v;
  }

 private:
  std::size_t Size() const { return 3 * static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_); }
  int width_, height_;
  std::vector<double> sum_, sum_sq_;
  int passes_ = 0;
};

vrli::Film ToFilm(const std::vector<double>& rgb, int width, int height);
std::vector<double> FromFilm(const vrli::Film& film);

}  // namespace vrl_compare
