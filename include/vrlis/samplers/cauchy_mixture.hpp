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
#include <cstdint>
#include <string_view>

#include "../angle/segment_sampler.hpp"
#include "cauchy_lobe.hpp"

namespace vrlis {

template <typename R>
class CauchyMixtureAngle {
 public:
  using Real = R;
  CauchyMixtureAngle(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom) : CauchyMixtureAngle(PhaseProduct<Real>(q, dom)) {}

  // A batch's fits and samples in vector lanes (CauchyLobesLanes; Henyey-Greenstein point
  // lobes, two components): out[i] is sample_pdf(u[i]) of lane i's query, to rounding. The
  // steps are sample_pdf's in loops over the lanes, the sines too (WidenedSinCosLanes: the same
  // order of samples as one query at a time).
  template <int kSize>
  using TargetLanes = typename PhaseProduct<Real>::template Lanes<kSize, false>;
  template <int kSize>
  static void SampleLanes(const TargetLanes<kSize>& target, const Real* u, int lanes, SegmentSample<Real>* out) {
    const CauchyLobesLanes<Real, kSize> fits(target, lanes);
    Real rest[kSize], s[kSize];
    std::int32_t second[kSize];  // (as wide as the floats, as AngleFrameLanes::on_line)
    for (int i = 0; i < lanes; ++i) {
      const Component pick = Choose<true>(u[i], 2);
      rest[i] = pick.rest, second[i] = pick.second;
      s[i] = pick.rest * SelectLanes(pick.second, fits.mass[1][i], fits.mass[0][i]);
    }
    Widened<Real> sin[kSize], cos[kSize];
    WidenedSinCosLanes(s, lanes, sin, cos);
    for (int i = 0; i < lanes; ++i) {
      const Real w = target.width[i];
      const TruncatedCauchy<Real> lobe[2] = {fits.lobe(0, i, w), fits.lobe(1, i, w)};
      out[i] = Finish<true>(lobe, fits.count[i], 2, w, u[i], {second[i] != 0, rest[i]}, {sin[i], cos[i]});
    }
  }

  // Component k = floor(n u) takes the rest of n u, so one uniform number serves both choices.
  // With every lobe flat the mixture is uniform and u maps as in equiangular sampling.
  Real sample(Real u) const { return sample_pdf(u).t; }
  // Both components' densities are needed at the sample whichever one produced it.
  SegmentSample<Real> sample_pdf(Real u) const {
    if (fit_.count == 0) return {u * width_, 1 / width_};  // (g = 0: no sine to take)
    const Component pick = Choose<false>(u, components_);
    const int k = pick.second ? 1 : 0;
    const SinCosPair<Widened<Real>> e = WidenedSinCos(pick.rest * fit_.lobe[k].mass());
    return Finish<false>(fit_.lobe.data(), fit_.count, components_, width_, u, pick, e);
  }

  Real pdf(Real delta) const { return Density<false>(fit_.lobe.data(), fit_.count, components_, width_, delta); }
  Real cdf(Real delta) const {
    Real sum = Real(components_ - fit_.count) * (delta / width_);
    for (int k = 0; k < fit_.count; ++k) sum += fit_.lobe[k].primitive(delta) / fit_.lobe[k].mass();
    return sum / Real(components_);
  }

 private:
  explicit CauchyMixtureAngle(const PhaseProduct<Real>& target)
      : fit_(target), width_(target.width()), components_(target.point_kind() == LobeKind::None ? 1 : 2) {}

  // The component a sample takes (the second, or the first) and the rest of n u. (Not
  // floor(n u) converted to an integer: n is 1 or 2, and a comparison stays in the lanes.)
  struct Component {
    bool second;
    Real rest;
  };
  template <bool kLanes>
  [[gnu::always_inline]] static Component Choose(Real u, int components) {
    const Real scaled = u * Real(components);
    const bool second = (components == 2) & (scaled >= 1);
    const Real rest = scaled - Pick<kLanes>(second, Real(1), Real(0));
    return {second, Pick<kLanes>(rest < 1, rest, Real(1))};
  }

  // The sample of component `pick` from (sin s, cos s) of its primitive's value s, and its
  // density; a component whose lobe the fit left out is uniform, and so is everything where
  // no lobe is kept (u itself then maps, as in equiangular sampling).
  template <bool kLanes>
  [[gnu::always_inline]] static SegmentSample<Real> Finish(const TruncatedCauchy<Real>* lobe, std::int32_t count,
                                                           int components, Real width, Real u, Component pick,
                                                           SinCosPair<Widened<Real>> e) {
    const TruncatedCauchy<Real>&first = lobe[0], &other = lobe[1];
    const bool k = pick.second;  // (selects, not a pick of a lobe: the loop over lanes vectorises)
    const TruncatedCauchy<Real> chosen(Pick<kLanes>(k, other.location(), first.location()),
                                       Pick<kLanes>(k, other.scale(), first.scale()),
                                       Pick<kLanes>(k, other.inv_scale(), first.inv_scale()), width,
                                       Pick<kLanes>(k, other.mass(), first.mass()));
    const bool kept = count > std::int32_t(pick.second);
    const Real uniform = Pick<kLanes>(count > 0, pick.rest, u) * width;
    const Real delta = Pick<kLanes>(kept, chosen.template inverse_primitive<kLanes>(e), uniform);
    return {delta, Density<kLanes>(lobe, count, components, width, delta)};
  }

  // The mean over the components of each one's density at delta, C_k / N_k, or 1 / width
  // for a lobe the fit left out (constant over the interval): over one division, in
  // Widened<Real> (the product of the two Cauchys' denominators underflows float for widths
  // below ~1e-10).
  template <bool kLanes>
  [[gnu::always_inline]] static Real Density(const TruncatedCauchy<Real>* lobe, std::int32_t count, int components,
                                             Real width, Real delta) {
    using W = Widened<Real>;
    W q[2], num[2];
    for (int k = 0; k < 2; ++k) {
      const bool kept = count > k;
      const W offset = W(delta) - lobe[k].location(), scale = lobe[k].scale();
      q[k] = Pick<kLanes>(kept, offset * offset + scale * scale, W(1));
      num[k] = Pick<kLanes>(kept, scale / W(lobe[k].mass()), Pick<kLanes>(k < components, 1 / W(width), W(0)));
    }
    return Real((num[0] * q[1] + num[1] * q[0]) / (W(components) * q[0] * q[1]));
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
  template <typename Real>
  using Sampler = CauchyMixture<Real>;
};

}  // namespace vrlis
