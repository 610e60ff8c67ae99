#pragma once
// The Cauchy mixture of Oppitz's thesis (docs/maths.md#cauchy-mixture): the two Cauchys of
// the thesis's fit, each truncated to the angle interval and normalised there on its own,
// mixed with equal weights, as the thesis author's implementation does; sampling picks a
// component, then inverts one arctangent. A lobe constant over the interval (exactly, as at
// g = 0, or to rounding), which the fit leaves out, keeps its weight as a uniform component,
// so g = 0 is equiangular sampling exactly.
//
// Because a component is chosen first, sample() is not the CDF's inverse: invert() returns
// the mixture CDF, and invert(sample(U)) is uniform for uniform U but differs from U.
#include <algorithm>
#include <string_view>

#include "../angle/segment_sampler.hpp"
#include "cauchy_lobe.hpp"

namespace vrlis {

template <typename R>
class CauchyMixtureAngle {
 public:
  using Real = R;
  CauchyMixtureAngle(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom) : CauchyMixtureAngle(PhaseProduct<Real>(q, dom)) {}

  // A batch's fits in vector lanes (CauchyLobesLanes; Henyey-Greenstein point lobes, two
  // components), each then sampled at u[i] one lane at a time: out[i] is sample_pdf(u[i]) of
  // lane i's query, to rounding.
  template <int kSize>
  using TargetLanes = typename PhaseProduct<Real>::template Lanes<kSize>;
  template <int kSize>
  static void SampleLanes(const TargetLanes<kSize>& target, const Real* u, int lanes, SegmentSample<Real>* out) {
    const CauchyLobesLanes<Real, kSize> fits(target, lanes);
    for (int i = 0; i < lanes; ++i) out[i] = CauchyMixtureAngle(fits.lobes(i, target.width[i]), target.width[i], 2).sample_pdf(u[i]);
  }

  // Component k = floor(n u) takes the rest of n u, so one uniform number serves both choices.
  // With every lobe flat the mixture is uniform and u maps as in equiangular sampling.
  Real sample(Real u) const {
    if (fit_.count == 0) return u * width_;
    int k = std::min(int(u * components_), components_ - 1);
    Real rest = std::min(u * components_ - k, Real(1));
    return k < fit_.count ? fit_.lobe[k].inverse_primitive(rest * fit_.lobe[k].mass()) : rest * width_;
  }

  Real pdf(Real delta) const {
    return Mix([delta](const TruncatedCauchy<Real>& c) { return c.density(delta); }, 1 / width_);
  }
  // Both components' densities are needed at the sample whichever one produced it.
  SegmentSample<Real> sample_pdf(Real u) const {
    Real delta = sample(u);
    return {delta, pdf(delta)};
  }
  Real cdf(Real delta) const {
    return Mix([delta](const TruncatedCauchy<Real>& c) { return c.primitive(delta); }, delta / width_);
  }

 private:
  explicit CauchyMixtureAngle(const PhaseProduct<Real>& target)
      : CauchyMixtureAngle(CauchyLobes<Real>(target), target.width(), target.point_kind() == LobeKind::None ? 1 : 2) {}
  CauchyMixtureAngle(const CauchyLobes<Real>& fit, Real width, int components)
      : fit_(fit), width_(width), components_(components) {}

  // The mean over the components of f(lobe_k) / mass_k, for f a lobe's density or primitive
  // at one offset; a lobe the fit left out (constant over the interval) is the uniform
  // component. (f a lambda, not a member pointer: GCC inlines it.)
  template <typename F>
  Real Mix(F f, Real uniform) const {
    Real sum = Real(components_ - fit_.count) * uniform;
    for (int k = 0; k < fit_.count; ++k) sum += f(fit_.lobe[k]) / fit_.lobe[k].mass();
    return sum / Real(components_);
  }

  CauchyLobes<Real> fit_;
  Real width_;
  int components_;  // one per phase lobe of the query: 2, or 1 for a point light
};

template <typename Real = float>
using CauchyMixture = SegmentSampler<CauchyMixtureAngle<Real>>;

// Its entry in the run-time sampler tables (method.hpp).
struct CauchyMixtureEntry {
  static constexpr std::string_view kName = "cauchy-mixture";
  static constexpr bool kRoundTripInDistribution = true;  // sample() picks a component first
  static constexpr bool kThesis = true;
  template <typename Real>
  using Sampler = CauchyMixture<Real>;
};

}  // namespace vrlis
