#pragma once
// A Cauchy density in the angle domain, truncated to [0, width], and the thesis's fit of one
// to each phase lobe. Shared by the Cauchy sum and the Cauchy mixture.
//
// With x = (theta - mu) / gamma, the primitive atan(x) - atan(x_a) is the argument of
// (1 + i x)(1 - i x_a), i.e. of z(delta) = gamma (1 + x x_a) + i delta once scaled by gamma.
// Working with z keeps the truncated mass exact for tiny gamma and peaks near an end.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "../angle/phase_product.hpp"

namespace vrlis {

// (sin s, cos s) in Widened<Real>, for a sample's solve. In float, sincosf (glibc: within
// an ulp, computed in double and rounded, so each of sin and cos follows s monotonically)
// suffices: the pair's angle is s to about an ulp, as if u had an ulp more rounding (the
// round trip allows hundreds), and it never decreases as s increases, so samples keep
// their order; the solve that follows, where digits cancel, stays in double.
template <typename Real>
SinCosPair<Widened<Real>> WidenedSinCos(Real s) {
  SinCosPair<Real> e = SinCos(s);
  return {e.sin, e.cos};
}
// The same for a batch's lanes, in a loop of its own: in float SinCosRounded, which has the
// same two properties and vectorises (libm's sincosf, one lane at a time, took a sixth of a
// batch's samples). The two differ by an ulp in about one value in a hundred (sincosf is not
// always the nearest float), within the rounding a batch's sample may differ from one query's.
template <typename Real>
void WidenedSinCosLanes(const Real* s, int lanes, Widened<Real>* sin, Widened<Real>* cos) {
  for (int i = 0; i < lanes; ++i) {
    SinCosPair<Widened<Real>> e;
    if constexpr (std::is_same_v<Real, float>) {
      const SinCosPair<float> f = SinCosRounded(s[i]);
      e = {f.sin, f.cos};
    } else {
      e = WidenedSinCos(s[i]);
    }
    sin[i] = e.sin, cos[i] = e.cos;
  }
}

template <typename Real>
class TruncatedCauchy {
 public:
  TruncatedCauchy() = default;
  // location: offset of the peak from theta_a (may lie outside the interval); inv_scale:
  // 1 / scale, passed in because a fit has it without a division of its own (pi times the
  // lobe's peak value), which keeps one division off the fit's critical path.
  TruncatedCauchy(Real location, Real scale, Real inv_scale, Real width)
      : location_(location), scale_(scale), inv_scale_(inv_scale), width_(width), mass_(primitive(width)) {}
  // With its mass computed elsewhere (in lanes: CauchyLobesLanes).
  TruncatedCauchy(Real location, Real scale, Real inv_scale, Real width, Real mass)
      : location_(location), scale_(scale), inv_scale_(inv_scale), width_(width), mass_(mass) {}

  // gamma / ((delta - mu)^2 + gamma^2): pi times the Cauchy density; integrates to mass().
  Real density(Real delta) const { return scale_ / (Sqr(delta - location_) + Sqr(scale_)); }
  // Its integral over [0, delta]: arg z(delta), z = Re(delta) + i delta.
  // (Branch-free: its octant is random across queries.)
  Real primitive(Real delta) const { return Atan2Lanes(delta, Re(delta)); }
  // The delta whose primitive is s, for s in [0, mass()]: delta cos s = Re(delta) sin s.
  // Solved in double for float: next to a narrow peak the denominator cancels, and a float
  // solve would reverse neighbouring samples.
  Real inverse_primitive(Real s) const { return inverse_primitive<false>(WidenedSinCos(s)); }
  // The same from (sin s, cos s); kLanes: branch-free, for a loop over a batch's samples.
  template <bool kLanes>
  [[gnu::always_inline]] Real inverse_primitive(SinCosPair<Widened<Real>> e) const {
    using W = Widened<Real>;
    const W ratio = W(location_) * inv_scale_, denom = e.cos + ratio * e.sin;
    const Real delta = Real((scale_ + location_ * ratio) * e.sin / denom);
    return Pick<kLanes>(denom > 0, PickClamp<kLanes>(delta, Real(0), width_), width_);
  }
  Real mass() const { return mass_; }
  Real location() const { return location_; }
  Real scale() const { return scale_; }
  Real inv_scale() const { return inv_scale_; }
  // Re z(delta) = gamma + mu (mu - delta) / gamma, in this factored form: expanded, its
  // two terms are ~1/gamma and cancel next to the peak (every digit for |g| -> 1).
  Real Re(Real delta) const { return scale_ + location_ * ((location_ - delta) * inv_scale_); }

 private:
  Real location_ = 0, scale_ = 1, inv_scale_ = 1, width_ = 0, mass_ = 0;
};

namespace detail {
// One lobe's Cauchy under the thesis's fit (below): its location, scale, 1 / scale, truncated
// mass, and whether it is kept. kLanes: branch-free, every case computed, for a loop over a
// batch's queries; otherwise the mass only for a kept lobe.
template <typename Real>
struct CauchyLobeFit {
  Real location = 0, scale = 1, inv_scale = 1, mass = 0;
  bool kept = false;
};
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline CauchyLobeFit<Real> FitCauchyLobe(bool flat, Real peak, PhaseFraction<Real> peak_value,
                                                                Real width) {
  // Offsets near the peak are resolved to an ulp of (width + |peak|); a narrower Cauchy
  // (the thesis's fit for |g| > ~0.995 in float) cannot be sampled and inverted consistently.
  const Real eps = std::numeric_limits<Real>::epsilon();
  const Real extent = width + std::abs(peak), pi_num = kPi<Real> * peak_value.num;
  const Real scale = peak_value.den / pi_num, inv_scale = pi_num / peak_value.den;
  // Constant over the interval to the last digit, a flat lobe: so wide that it is over the
  // whole extent, or so far from the interval that its relative change there (at most
  // 2 width / distance) is below epsilon. The latter is no mere shortcut: there the
  // primitives are ~ width scale / distance^2 and underflow to subnormals (float widths of
  // ~1e-36 rad), whose few digits broke the round trip.
  const Real distance = Pick<kLanes>(peak < 0, -peak, Pick<kLanes>(peak > width, peak - width, Real(0)));
  CauchyLobeFit<Real> out;
  out.kept = !flat & (extent >= scale * std::sqrt(eps)) & !(2 * width < eps * distance);
  if constexpr (!kLanes)
    if (!out.kept) return out;
  const Real resolvable = 64 * eps * extent;
  const bool widened = scale < resolvable;
  out.location = peak;
  out.scale = Pick<kLanes>(widened, resolvable, scale);
  out.inv_scale = Pick<kLanes>(widened, 1 / resolvable, inv_scale);
  out.mass = TruncatedCauchy<Real>(out.location, out.scale, out.inv_scale, width, 0).primitive(width);
  return out;
}
}  // namespace detail

// The thesis's fit (docs/maths.md#cauchy-fit): a Cauchy located at the lobe's peak whose peak value 1 / (pi gamma)
// equals the lobe's peak value. Lobes constant in theta only scale the product and are
// left out (so that g = 0 reduces to equiangular sampling exactly).
template <typename Real>
struct CauchyLobes {
  std::array<TruncatedCauchy<Real>, 2> lobe;
  int count = 0;

  CauchyLobes() = default;
  explicit CauchyLobes(const PhaseProduct<Real>& target) {
    if (!target.segment_lobe_flat()) Add(target.segment_peak(), target.segment_peak_value(), target.width());
    if (!target.point_lobe_flat()) Add(target.point_peak(), target.point_peak_value(), target.width());
  }

 private:
  void Add(Real peak, PhaseFraction<Real> peak_value, Real width) {
    const detail::CauchyLobeFit<Real> f = detail::FitCauchyLobe<false>(false, peak, peak_value, width);
    if (f.kept) lobe[count++] = TruncatedCauchy<Real>(f.location, f.scale, f.inv_scale, width, f.mass);
  }
};

// The fits of a batch's camera steps (PhaseProduct::Lanes, one query per lane) in vector
// lanes, CauchyLobes' rules for each lobe computed in every lane and picked by selects
// (square roots by Newton steps: within 3 ulp of CauchyLobes). lobes(i) is lane i's fit.
template <typename Real, int kSize>
struct CauchyLobesLanes {
  Real location[2][kSize], scale[2][kSize], inv_scale[2][kSize], mass[2][kSize];
  std::int32_t count[kSize];

  CauchyLobesLanes(const typename PhaseProduct<Real>::template Lanes<kSize, false>& target, int lanes) {
    const Real g = target.g, ag = std::abs(g);
    const PhaseFraction<Real> segment_value{HenyeyGreensteinPeak(g), 1};
    for (int i = 0; i < lanes; ++i) {
      const Real w = target.width[i];
      const auto segment =
          detail::FitCauchyLobe<true>(g == 0, SelectLanes(g > 0, target.lower[i], target.upper[i]), segment_value, w);
      const Real d = HenyeyGreensteinBase<true>(ag, target.one_minus_r[i], 1 + target.r[i]);
      const auto point = detail::FitCauchyLobe<true>(target.point_lobe_flat(i), target.point_peak(i),
                                                     {(1 - ag) * (1 + ag), 4 * kPi<Real> * d * SqrtLanes(d)}, w);
      // In CauchyLobes' order: the segment's first, where it is kept.
      location[0][i] = SelectLanes(segment.kept, segment.location, point.location);
      scale[0][i] = SelectLanes(segment.kept, segment.scale, point.scale);
      inv_scale[0][i] = SelectLanes(segment.kept, segment.inv_scale, point.inv_scale);
      mass[0][i] = SelectLanes(segment.kept, segment.mass, point.mass);
      location[1][i] = point.location, scale[1][i] = point.scale, inv_scale[1][i] = point.inv_scale;
      mass[1][i] = point.mass;
      count[i] = std::int32_t(segment.kept) + std::int32_t(point.kept);
    }
  }

  // Lobe k of lane i over [0, width] (whether kept or not: count[i] says).
  [[gnu::always_inline]] TruncatedCauchy<Real> lobe(int k, int i, Real width) const {
    return TruncatedCauchy<Real>(location[k][i], scale[k][i], inv_scale[k][i], width, mass[k][i]);
  }
  // Lane i's fit over [0, width].
  CauchyLobes<Real> lobes(int i, Real width) const {
    CauchyLobes<Real> out;
    out.count = count[i];
    for (int k = 0; k < count[i]; ++k)
      out.lobe[k] = TruncatedCauchy<Real>(location[k][i], scale[k][i], inv_scale[k][i], width, mass[k][i]);
    return out;
  }
};

}  // namespace vrlis
