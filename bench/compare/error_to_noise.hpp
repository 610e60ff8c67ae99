#pragma once
// Whether a method's image agrees with the reference within its noise: the squared error of
// its mean image over the noise expected of both images, and the range that ratio keeps 95% of
// the time when nothing is biased.
//
// The range is not a constant. An image's errors are correlated across its pixels (a light
// path lights many of them), so the summed squared error is a sum of few independent squares,
// about chi-square on k degrees of freedom over k with k = tr(C)^2 / tr(C^2) for the error's
// covariance C, and k can be as small as 4 or 5 (fog and corner, lit through a dense medium:
// an unbiased ratio then lands anywhere in about 0.2-2.5). k comes from
// the images' own samples: the deviations of a study's replicate means from their mean, and of
// a reference's passes from theirs, give tr(C) and tr(C^2) (each unbiased for Gaussian
// samples, Bai and Saranadasa 1996).
#include <vector>

namespace vrlis::compare {

struct ErrorToNoise {
  double ratio = 0;         // squared error over the expected noise of both images
  double dof = 0;           // k, the error's effective degrees of freedom
  double low = 0, high = 0;  // the ratio's 95% range when unbiased: chi-square_k / k quantiles
  bool Outside() const { return ratio < low || ratio > high; }
};

// k = tr(Sigma)^2 / tr(Sigma^2) for the covariance Sigma of independent, identically
// distributed images (at least 3): a study's replicate means, a reference's passes. Their mean's
// error has the same k. An estimate of tr(Sigma^2) at or below zero (no sign of correlation)
// gives the number of values.
double NoiseDof(const std::vector<std::vector<double>>& samples);

// replicate_means: each replicate's mean image (the same number of passes each, at least 3);
// noise: the pooled mean's variance per value; reference, reference_noise and reference_dof: the
// reference image, its mean's variance per value and its NoiseDof. The two images' errors are
// independent; k of their difference is taken at its least, as if their covariances had one
// shape (Cauchy-Schwarz), so the range is, if anything, too wide.
ErrorToNoise ErrorAgainstNoise(const std::vector<std::vector<double>>& replicate_means,
                               const std::vector<double>& noise, const std::vector<double>& reference,
                               const std::vector<double>& reference_noise, double reference_dof,
                               double confidence = 0.95);

}  // namespace vrlis::compare
