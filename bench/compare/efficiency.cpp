#include "efficiency.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>

#include <boost/math/distributions/students_t.hpp>

namespace vrlis::compare {
namespace {

double MeanWithout(const std::vector<double>& x, std::size_t skip) {
  double sum = 0;
  for (std::size_t i = 0; i < x.size(); ++i)
    if (i != skip) sum += x[i];
  return sum / static_cast<double>(x.size() - (skip < x.size() ? 1 : 0));
}

// Per replicate, variance x seconds.
std::vector<double> Costs(const Replicates& r) {
  std::vector<double> c(r.variance.size());
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = r.variance[i] * r.seconds[i];
  return c;
}

}  // namespace

double PooledVariance(const Replicates& r) { return MeanWithout(r.variance, r.variance.size()); }
double PooledSeconds(const Replicates& r) { return MeanWithout(r.seconds, r.seconds.size()); }
double Efficiency(const Replicates& r) {
  const std::vector<double> c = Costs(r);
  return 1 / MeanWithout(c, c.size());
}

RatioInterval EfficiencyRatio(const Replicates& a, const Replicates& b, double confidence) {
  const std::size_t n = a.variance.size();
  if (n < 3 || b.variance.size() != n || a.seconds.size() != n || b.seconds.size() != n)
    throw std::invalid_argument("EfficiencyRatio needs the same number (>= 3) of replicates on both sides");
  const std::vector<double> ca = Costs(a), cb = Costs(b);
  // log(E_a / E_b) from the replicates other than `skip` (all of them if skip is out of range).
  auto log_ratio = [&](std::size_t skip) { return std::log(MeanWithout(cb, skip)) - std::log(MeanWithout(ca, skip)); };
  const double whole = log_ratio(n);
  std::vector<double> leave_one(n);
  for (std::size_t i = 0; i < n; ++i) leave_one[i] = log_ratio(i);
  const double mean = std::accumulate(leave_one.begin(), leave_one.end(), 0.0) / static_cast<double>(n);
  double ss = 0;
  for (double x : leave_one) ss += (x - mean) * (x - mean);
  const double se = std::sqrt(ss * static_cast<double>(n - 1) / static_cast<double>(n));
  const boost::math::students_t t(static_cast<double>(n - 1));
  const double half = boost::math::quantile(t, 0.5 + confidence / 2) * se;
  if (!std::isfinite(whole) || !std::isfinite(half)) return {std::exp(whole), 0, INFINITY};  // a noiseless side
  return {std::exp(whole), std::exp(whole - half), std::exp(whole + half)};
}

}  // namespace vrlis::compare
