#pragma once
// Per-pixel running sums of passes: the mean image, the per-pass variance of every pixel
// (estimated from the passes themselves) and the variance of the mean.
#include <algorithm>
#include <cstddef>
#include <vector>

#include <vrlis_integration/film.hpp>

namespace vrl_compare {

// A pass as RGB doubles, pixel by pixel.
std::vector<double> FromFilm(const vrli::Film& film);
vrli::Film ToFilm(const std::vector<double>& rgb, int width, int height);

class PassStatistics {
 public:
  explicit PassStatistics(std::size_t values = 0) : sum_(values), sum_sq_(values) {}

  void Add(const std::vector<double>& pass) {
    for (std::size_t i = 0; i < pass.size(); ++i) {
      sum_[i] += pass[i];
      sum_sq_[i] += pass[i] * pass[i];
    }
    ++passes_;
  }
  void Add(const vrli::Film& pass) { Add(FromFilm(pass)); }

  int passes() const { return passes_; }

  std::vector<double> Mean() const {
    std::vector<double> m(sum_.size());
    for (std::size_t i = 0; i < m.size(); ++i) m[i] = sum_[i] / passes_;
    return m;
  }

  // Unbiased variance of one pass, per pixel and channel.
  std::vector<double> PassVariance() const {
    std::vector<double> v(sum_.size());
    if (passes_ < 2) return v;
    for (std::size_t i = 0; i < v.size(); ++i) {
      double mean = sum_[i] / passes_;
      v[i] = std::max((sum_sq_[i] - passes_ * mean * mean) / (passes_ - 1.0), 0.0);
    }
    return v;
  }

  // The per-pass variance averaged over pixels and channels: the image's noise per pass.
  double MeanPassVariance() const {
    std::vector<double> v = PassVariance();
    double sum = 0;
    for (double x : v) sum += x;
    return v.empty() ? 0 : sum / static_cast<double>(v.size());
  }

  std::vector<double> VarianceOfMean() const {
    std::vector<double> v = PassVariance();
    for (double& x : v) x /= passes_;
    return v;
  }

 private:
  std::vector<double> sum_, sum_sq_;
  int passes_ = 0;
};

}  // namespace vrl_compare
