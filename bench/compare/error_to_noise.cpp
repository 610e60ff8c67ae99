#include "error_to_noise.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <boost/math/distributions/chi_squared.hpp>

namespace vrlis::compare {
namespace {

// The mean of at least 3 images of one size.
std::vector<double> MeanImage(const std::vector<std::vector<double>>& samples) {
  const std::size_t r = samples.size(), values = r ? samples[0].size() : 0;
  if (r < 3) throw std::invalid_argument("the noise's degrees of freedom need at least 3 images");
  std::vector<double> mean(values, 0.0);
  for (const auto& x : samples) {
    if (x.size() != values) throw std::invalid_argument("the noise's degrees of freedom need images of one size");
    for (std::size_t i = 0; i < values; ++i) mean[i] += x[i] / static_cast<double>(r);
  }
  return mean;
}

// NoiseDof of samples whose mean (MeanImage) is given.
double DofAbout(const std::vector<std::vector<double>>& samples, const std::vector<double>& mean) {
  const std::size_t r = samples.size(), values = mean.size();
  // The sample covariance S over n = r - 1 degrees of freedom, through the Gram matrix of the
  // deviations (r x r, not values x values): tr S and tr S^2, then the unbiased tr(Sigma^2)
  // and tr(Sigma)^2 from them.
  std::vector<std::vector<double>> deviation(r, std::vector<double>(values));
  for (std::size_t a = 0; a < r; ++a)
    for (std::size_t i = 0; i < values; ++i) deviation[a][i] = samples[a][i] - mean[i];
  const double n = static_cast<double>(r - 1);
  double tr = 0, tr_sq = 0;
  for (std::size_t a = 0; a < r; ++a)
    for (std::size_t b = a; b < r; ++b) {
      double dot = 0;
      for (std::size_t i = 0; i < values; ++i) dot += deviation[a][i] * deviation[b][i];
      if (a == b) tr += dot / n;
      tr_sq += (a == b ? 1 : 2) * dot * dot / (n * n);
    }
  const double sigma_sq = n * n / ((n - 1) * (n + 2)) * (tr_sq - tr * tr / n);
  const double trace_squared = tr * tr - 2 * sigma_sq / n;
  const double most = static_cast<double>(values);
  return sigma_sq > 0 && trace_squared > 0 ? std::clamp(trace_squared / sigma_sq, 1.0, most) : most;
}

}  // namespace

double NoiseDof(const std::vector<std::vector<double>>& samples) { return DofAbout(samples, MeanImage(samples)); }

ErrorToNoise ErrorAgainstNoise(const std::vector<std::vector<double>>& replicate_means,
                               const std::vector<double>& noise, const std::vector<double>& reference,
                               const std::vector<double>& reference_noise, double reference_dof,
                               double confidence) {
  const std::size_t values = reference.size();
  const std::vector<double> pooled = MeanImage(replicate_means);
  if (pooled.size() != values || noise.size() != values || reference_noise.size() != values || !(reference_dof >= 1))
    throw std::invalid_argument("ErrorAgainstNoise needs images of one size and a reference's k >= 1");
  const double dof = DofAbout(replicate_means, pooled);
  ErrorToNoise out;
  double error = 0, own = 0, of_reference = 0;
  for (std::size_t i = 0; i < values; ++i) {
    error += (pooled[i] - reference[i]) * (pooled[i] - reference[i]);
    own += noise[i];
    of_reference += reference_noise[i];
  }
  const double expected = own + of_reference;
  out.ratio = expected > 0 ? error / expected : 0;
  // tr(C^2) of each part is its trace squared over its k; the sum's at most (sqrt + sqrt)^2.
  const double root = own / std::sqrt(dof) + of_reference / std::sqrt(reference_dof);
  out.dof = root > 0 ? std::max(1.0, expected * expected / (root * root)) : static_cast<double>(values);

  const boost::math::chi_squared chi(out.dof);
  out.low = boost::math::quantile(chi, (1 - confidence) / 2) / out.dof;
  out.high = boost::math::quantile(chi, (1 + confidence) / 2) / out.dof;
  return out;
}

}  // namespace vrlis::compare
