#pragma once
// Running statistics of a stream of values (for instance the weights f / pdf of an
// estimator): count, mean, unbiased variance, variance of the mean and largest value, in
// one pass and constant memory. Welford's update keeps the variance accurate where the
// textbook sum of squares minus n mean^2 cancels (heavy-tailed weights, a large mean
// beside a small spread); merge() combines two accumulators exactly as if one had seen
// both streams (Chan, Golub and LeVeque's pairwise update), for per-thread partial sums.
// Standard library only, so that users measuring their own estimators can use it.
#include <cmath>
#include <cstdint>
#include <limits>

namespace vrlis {

class RunningMoments {
 public:
  void add(double x) {
    ++count_;
    const double d = x - mean_;
    mean_ += d / static_cast<double>(count_);
    m2_ += d * (x - mean_);
    if (x > max_) max_ = x;
  }

  void merge(const RunningMoments& other) {
    if (other.count_ == 0) return;
    if (count_ == 0) {
      *this = other;
      return;
    }
    const double n = static_cast<double>(count_ + other.count_);
    const double d = other.mean_ - mean_;
    mean_ += d * (static_cast<double>(other.count_) / n);
    m2_ += other.m2_ + d * d * (static_cast<double>(count_) * static_cast<double>(other.count_) / n);
    count_ += other.count_;
    if (other.max_ > max_) max_ = other.max_;
  }

  std::int64_t count() const { return count_; }
  // 0 before the first value.
  double mean() const { return mean_; }
  // Unbiased (divides by n - 1); 0 below two values.
  double variance() const { return count_ > 1 ? m2_ / static_cast<double>(count_ - 1) : 0.0; }
  // The variance of mean() as an estimate of the expectation: variance() / n.
  double variance_of_mean() const { return count_ > 0 ? variance() / static_cast<double>(count_) : 0.0; }
  double standard_error() const { return std::sqrt(variance_of_mean()); }
  // The largest value added; -infinity before the first (NaNs are never the largest).
  double max() const { return max_; }

 private:
  std::int64_t count_ = 0;
  double mean_ = 0, m2_ = 0;  // m2_: the sum of squared deviations from the mean
  double max_ = -std::numeric_limits<double>::infinity();
};

}  // namespace vrlis
