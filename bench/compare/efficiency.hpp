#pragma once
// Efficiency, 1 / (per-pass variance x seconds per pass) averaged over replicates, and
// confidence intervals for the ratio of two samplers' efficiencies from independent replicate
// runs: a delete-one jackknife over replicates of the log ratio, with Student's t on R - 1
// degrees of freedom (docs/compare/README.md says why this and not a bootstrap over passes).
#include <vector>

namespace vrlis::compare {

// One sampler's replicates, all of the same number of passes: per replicate, the per-pass
// variance (mean over pixels) and the mean seconds per pass.
struct Replicates {
  std::vector<double> variance, seconds;
};

struct RatioInterval {
  double point = 0, low = 0, high = 0;
  bool Above(double x) const { return low > x; }
};

// Means over the replicates.
double PooledVariance(const Replicates& r);
double PooledSeconds(const Replicates& r);
// 1 / the mean over replicates of variance x seconds: a replicate's squared error at one
// second of rendering, whose mean is what a user who cannot choose the seed gets. Not
// 1 / (PooledVariance x PooledSeconds), which charges replicates that differ (the effort
// control's choices) for a variance of some and the time of others (docs/compare/README.md).
double Efficiency(const Replicates& r);

// Efficiency of a over efficiency of b. The two must come from the same replicate seeds
// (the pairing is what makes the interval narrow) and hold at least 3 replicates.
RatioInterval EfficiencyRatio(const Replicates& a, const Replicates& b, double confidence = 0.95);

}  // namespace vrlis::compare
