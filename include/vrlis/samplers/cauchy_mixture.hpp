#pragma once
// The 2023 TU Wien thesis's solution 2 (docs/maths.md#cauchy-mixture): a mixture of the two Cauchys, each normalised over the interval
// on its own; sampling picks a component, then inverts one arctangent.
//
// Weights (the thesis leaves them open): near the peak of lobe k the product is about
// (lobe k) x (the other lobe's value there), so component k gets the weight
// mass_k x other_lobe(peak_k clamped into the interval). This is the mixture that matches
// the product at both peaks; equal weights would waste half the samples whenever one peak
// dominates, and weights proportional to mass_k alone give back the Cauchy sum.
//
// Because a component is chosen first, sample() is not the CDF's inverse: invert() returns
// the mixture CDF, and invert(sample(U)) is uniform for uniform U but differs from U.
#include <string_view>

#include "../angle/segment_sampler.hpp"
#include "cauchy_lobe.hpp"

namespace vrlis {

template <typename R>
class CauchyMixtureAngle {
 public:
  using Real = R;
  CauchyMixtureAngle(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom) : CauchyMixtureAngle(PhaseProduct<Real>(q, dom)) {}

  Real sample(Real u) const {
    switch (fit_.count) {
      case 0: return u * width_;
      case 1: return fit_.lobe[0].inverse_primitive(u * fit_.lobe[0].mass());
    }
    if (u < weight0_ || weight0_ >= 1)
      return fit_.lobe[0].inverse_primitive(std::min(u / weight0_, Real(1)) * fit_.lobe[0].mass());
    return fit_.lobe[1].inverse_primitive(std::min((u - weight0_) / (1 - weight0_), Real(1)) * fit_.lobe[1].mass());
  }

  Real pdf(Real delta) const { return Mix(delta, &TruncatedCauchy<Real>::density, 1 / width_); }
  // Both components' densities are needed at the sample whichever one produced it.
  SegmentSample<Real> sample_pdf(Real u) const {
    Real delta = sample(u);
    return {delta, pdf(delta)};
  }
  Real cdf(Real delta) const { return Mix(delta, &TruncatedCauchy<Real>::primitive, delta / width_); }
  Real weight0() const { return weight0_; }

 private:
  explicit CauchyMixtureAngle(const PhaseProduct<Real>& target) : fit_(target), width_(target.width()) {
    if (fit_.count < 2) return;
    Real w[2];
    for (int k = 0; k < 2; ++k) {
      Real at = Clamp(fit_.lobe[k].location(), Real(0), width_);
      w[k] = fit_.lobe[k].mass() * (fit_.from_segment[k] ? target.point_lobe(at) : target.segment_lobe(at));
    }
    weight0_ = w[0] + w[1] > 0 ? w[0] / (w[0] + w[1]) : Real(0.5);
  }

  // sum_k weight_k f_k(delta) / mass_k for f the density or the primitive.
  Real Mix(Real delta, Real (TruncatedCauchy<Real>::*f)(Real) const, Real uniform) const {
    if (fit_.count == 0) return uniform;
    const TruncatedCauchy<Real>& c0 = fit_.lobe[0];
    Real first = (c0.*f)(delta) / c0.mass();
    if (fit_.count == 1) return first;
    const TruncatedCauchy<Real>& c1 = fit_.lobe[1];
    return weight0_ * first + (1 - weight0_) * (c1.*f)(delta) / c1.mass();
  }

  CauchyLobes<Real> fit_;
  Real width_;
  Real weight0_ = 1;
};

template <typename Real = float>
using CauchyMixture = SegmentSampler<CauchyMixtureAngle<Real>>;

// Its entry in the run-time sampler tables (method.hpp).
struct CauchyMixtureEntry {
  static constexpr std::string_view kName = "cauchy-mixture";
  static constexpr bool kRoundTripInDistribution = true;  // sample() picks a component first
  template <typename Real>
  using Sampler = CauchyMixture<Real>;
};

}  // namespace vrlis
