#pragma once
// Per-pixel running statistics of passes (vrlis::RunningMoments per pixel and channel): the
// mean image, the per-pass variance of every pixel (estimated from the passes themselves)
// and the variance of the mean.
#include <cstddef>
#include <vector>

#include <vrlis/core/running_moments.hpp>
#include <vrlis_integration/film.hpp>

namespace vrlis::compare {

// A pass as RGB doubles, pixel by pixel.
std::vector<double> FromFilm(const vrlis::integration::Film& film);
vrlis::integration::Film ToFilm(const std::vector<double>& rgb, int width, int height);

class PassStatistics {
 public:
  explicit PassStatistics(std::size_t values = 0) : values_(values) {}

  void Add(const std::vector<double>& pass) {
    for (std::size_t i = 0; i < pass.size(); ++i) values_[i].add(pass[i]);
    ++passes_;
  }
  void Add(const vrlis::integration::Film& pass) { Add(FromFilm(pass)); }

  int passes() const { return passes_; }

  std::vector<double> Mean() const { return Each(&vrlis::RunningMoments::mean); }
  // Unbiased variance of one pass, per pixel and channel.
  std::vector<double> PassVariance() const { return Each(&vrlis::RunningMoments::variance); }
  std::vector<double> VarianceOfMean() const { return Each(&vrlis::RunningMoments::variance_of_mean); }

  // The per-pass variance averaged over pixels and channels: the image's noise per pass.
  double MeanPassVariance() const {
    double sum = 0;
    for (const vrlis::RunningMoments& m : values_) sum += m.variance();
    return values_.empty() ? 0 : sum / static_cast<double>(values_.size());
  }

 private:
  std::vector<double> Each(double (vrlis::RunningMoments::*statistic)() const) const {
    std::vector<double> out;
    out.reserve(values_.size());
    for (const vrlis::RunningMoments& m : values_) out.push_back((m.*statistic)());
    return out;
  }

  std::vector<vrlis::RunningMoments> values_;  // one per pixel and channel
  int passes_ = 0;
};

}  // namespace vrlis::compare
