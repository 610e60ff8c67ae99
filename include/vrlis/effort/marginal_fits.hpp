#pragma once
// Which gathers VrlMarginal's fit is given to (EffortSettings::marginal_threshold): a score per
// gather from its bound, and the octave histogram of scores a renderer learns the threshold
// from (docs/maths.md#vrl-marginal-where).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "bounds.hpp"

namespace vrlis {


// The score by which VrlMarginal's fits are given (EffortSettings::marginal_threshold):
// score[i] is gather i's predicted second moment (weights[i] x MediumGatherBound)^2 (weights
// null: 1 each; NaN: 0), bound[i] the bound itself (the effort control's tight bound, which
// the call's decisions then need not take again). A function of the queries alone, not of
// any gather's numbers, so a density chosen by it leaves the estimator unbiased.
template <typename Real>
void MarginalFitScores(const RaySegment<Real>& camera, const Medium<Real>& m, const VrlSegment<Real>* vrls,
                       const Real* weights, int count, Real* bound, double* score) {
  for (int first = 0; first < count; first += kBoundBatch) {
    const int n = std::min(kBoundBatch, count - first);
    MediumGatherBounds(camera, vrls + first, n, m, static_cast<Real*>(nullptr), bound + first);
    for (int i = first; i < first + n; ++i) {
      const double s = Sqr(double(weights ? weights[i] : Real(1)) * double(bound[i]));
      score[i] = std::isnan(s) ? 0 : s;
    }
  }
}

// How many scores fell in each octave [2^(k - kOffset), 2^(k + 1 - kOffset)) (the ends
// clamped; zeros uncounted): what a renderer learns from a pass to set the next pass's
// marginal_threshold.
struct ScoreOctaves {
  static constexpr int kBins = 160, kOffset = 100;
  std::uint64_t count[kBins] = {};

  void Add(double score) {
    if (!(score > 0)) return;
    const int k = score < std::numeric_limits<double>::infinity() ? std::ilogb(score) + kOffset : kBins - 1;
    ++count[std::clamp(k, 0, kBins - 1)];
  }
  ScoreOctaves& operator+=(const ScoreOctaves& o) {
    for (int k = 0; k < kBins; ++k) count[k] += o.count[k];
    return *this;
  }
  std::uint64_t total() const {
    std::uint64_t n = 0;
    for (std::uint64_t c : count) n += c;
    return n;
  }
  // The lower end of the lowest octave such that the octaves from it up hold at most
  // `fraction` of the counted scores (to an octave: a threshold that fits about that share of
  // gathers); +infinity when none do, or nothing was counted.
  double Threshold(double fraction) const {
    const std::uint64_t n = total();
    const double limit = fraction * double(n);
    double above = 0, threshold = std::numeric_limits<double>::infinity();
    if (n == 0) return threshold;
    for (int k = kBins - 1; k >= 0; --k) {
      above += double(count[k]);
      if (above > limit) break;
      threshold = std::ldexp(1.0, k - kOffset);
    }
    return threshold;
  }
};

}  // namespace vrlis
