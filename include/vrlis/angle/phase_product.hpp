#pragma once
// The sampling target in the angle domain: the product of the segment lobe and the point
// lobe as functions of delta = theta - theta_a (docs/maths.md#lobes).
//
// Both lobes are evaluated from half-angle sines, so lobes with |g| -> 1 keep their shape
// next to an endpoint. In evaluate() (a fit's nodes), the half angles of both lobes are
// delta/2 minus a constant, so one SinCos(delta / 2) per node gives both by the subtraction
// formulas; their absolute error is a few ulp, as that of the angle itself.
#include <array>
#include <cstddef>
#include <limits>

#include "../core/phase.hpp"
#include "../core/lane_math.hpp"
#include "angle_domain.hpp"

namespace vrlis {

namespace detail {

// Offsets of theta = -pi/2 and +pi/2 from theta_a (tan_a = tan(theta_a)): the nearer pole's
// is the small atan2, the other's pi minus it.
template <typename Real>
struct PoleOffsets {
  Real lower, upper;
};
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline PoleOffsets<Real> PolesOf(Real tan_a) {
  Real near = Atan2Lanes(Real(1), std::abs(tan_a));
  return {Pick<kLanes>(tan_a >= 0, near - kPi<Real>, -near), Pick<kLanes>(tan_a >= 0, near, kPi<Real> - near)};
}

// The point lobe's axis in the plane of the segment and p (normal n: from the segment
// towards p): r, the length of its projection, 1 - r, and theta_e - theta_a, the angle of
// the projection rotated back by theta_a. kLanes as ReduceToAngles.
template <typename Real>
struct LobeInPlane {
  Real r, one_minus_r, theta_e;
};
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline LobeInPlane<Real> ProjectLobe(const Vec3<Real>& axis, const Vec3<Real>& n,
                                                            const Vec3<Real>& dir, Real tan_a, bool on_line) {
  Real a = -Dot(axis, n), b = Dot(axis, dir), c = Dot(axis, Cross(dir, n));
  // On the line the plane is arbitrary: keep only the part along the segment.
  if constexpr (kLanes) {
    c = SelectLanes(on_line, SqrtLanes(a * a + c * c), c);
    a = SelectLanes(on_line, Real(0), a);
  } else if (on_line) {
    c = std::sqrt(a * a + c * c);
    a = 0;
  }
  LobeInPlane<Real> out;
  Real r = PickSqrt<kLanes>(a * a + b * b);
  out.r = Pick<kLanes>(Real(1) < r, Real(1), r);
  out.one_minus_r = c * c / (1 + out.r);  // 1 - r from the out-of-plane part: exact as r -> 1
  out.theta_e = Atan2Lanes(b - tan_a * a, a + tan_a * b);
  return out;
}

// Of a peak at offset `base` and its images 2 pi apart, the one nearest the interval
// [0, width]: the one nearest its midpoint (the images are 2 pi apart, the interval at most pi
// wide), base - 2 pi k with k the integer nearest (base - width / 2) / (2 pi). For base in
// [-pi, 2 pi], k is -1, 0 or 1, found by two comparisons (not branches: the side is random
// across queries).
template <typename Real>
[[gnu::always_inline]] inline Real NearestPeak(Real base, Real width) {
  Real from_middle = base - width / 2;
  return base - 2 * kPi<Real> * (Real(from_middle > kPi<Real>) - Real(from_middle < -kPi<Real>));
}

// One Henyey-Greenstein lobe as a function of the sines and cosines of delta / 2: K d^(-3/2)
// with d = (1 - |g|)^2 + 2 |g| (1 - r) + 4 |g| r w^2, w the sine of its half angle from its
// peak (r = 1 for the segment lobe), w = from_sin sin(delta / 2) + from_cos cos(delta / 2).
template <typename Real>
struct LobeShape {
  Real from_sin = 0, from_cos = 0, base = 1, slope = 0, scale = kInvPi<Real> / 4;

  // rotation: sin and cos of the lobe's half angle at delta = 0. The half angle from the
  // peak is that one for g >= 0 and its complement for g < 0.
  [[gnu::always_inline]] static LobeShape Of(Real g, Real r, Real one_minus_r, SinCosPair<Real> rotation) {
    Real ag = std::abs(g);
    LobeShape s;
    s.from_sin = SelectLanes(g >= 0, rotation.cos, rotation.sin);  // (selects: loops over lobes vectorise)
    s.from_cos = SelectLanes(g >= 0, -rotation.sin, rotation.cos);
    s.base = Sqr(1 - ag) + 2 * ag * one_minus_r;
    s.slope = 4 * ag * r;
    s.scale = (1 - g) * (1 + g) / (4 * kPi<Real>);
    return s;
  }
  [[gnu::always_inline]] Real d(SinCosPair<Real> half) const {
    Real w = half.sin * from_sin + half.cos * from_cos;
    return base + slope * w * w;
  }
  template <Accuracy kAccuracy = Accuracy::Full>
  [[gnu::always_inline]] Real operator()(SinCosPair<Real> half) const {
    Real r = RsqrtLanes<kAccuracy>(d(half));
    return scale * (r * r * r);
  }
};

// Two lobes' product at the same half angle with one reciprocal square root, (d_a d_b)^(-3/2):
// each d is at least (1 - |g|)^2, so the product stays far inside float's range.
template <Accuracy kAccuracy = Accuracy::Full, typename Real>
[[gnu::always_inline]] inline Real LobeProduct(const LobeShape<Real>& a, const LobeShape<Real>& b, SinCosPair<Real> half) {
  Real r = RsqrtLanes<kAccuracy>(a.d(half) * b.d(half));
  return a.scale * b.scale * (r * r * r);
}

}  // namespace detail

template <typename Real>
class PhaseProduct {
 public:
  // A clamped-cosine lobe is zero over part of the domain; a fit must not put a sample
  // where its density is zero, so node values are kept above this fraction of the largest
  // (far below anything that changes the variance).
  static constexpr Real kRelativeFloor = std::numeric_limits<Real>::epsilon();

  PhaseProduct(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom)
      : g_(q.g), g_point_(q.lobe.g), kind_(q.lobe.kind), width_(dom.width()) {
    // (Arctangents here are branch-free: the octants are random across queries.)
    Real A = dom.tan_theta_a();
    const detail::PoleOffsets<Real> poles = detail::PolesOf<false>(A);
    lower_ = poles.lower;
    upper_ = poles.upper;
    if (kind_ == LobeKind::None) return;
    const detail::LobeInPlane<Real> lobe = detail::ProjectLobe<false>(q.lobe.axis, dom.normal(), q.dir, A, dom.on_line());
    r_ = lobe.r;
    one_minus_r_ = lobe.one_minus_r;
    theta_e_ = lobe.theta_e;
  }

  // The product at every offset in `delta` (a fit's nodes), in a branch-free loop that
  // compilers vectorise. Henyey-Greenstein lobes are detail::LobeShape's functions of sin and
  // cos of delta / 2; a clamped cosine is r cos(delta - theta_e) / pi, from the same pair by
  // the double-angle formulas. Accuracy::Fit for a fit's node values (core/lane_math.hpp);
  // Full is operator() to rounding (tests/lib/phase_product.cpp).
  template <Accuracy kAccuracy = Accuracy::Full, std::size_t N>
  void evaluate(const std::array<Real, N>& delta, std::array<Real, N>& out) const {
    // (Computed here, not in the constructor: the Cauchy fits never need them. Inline
    // sines: two independent libm calls cost more than the polynomial, which overlaps.)
    switch (kind_) {
      case LobeKind::HenyeyGreenstein: {
        const auto b = detail::LobeShape<Real>::Of(g_point_, r_, one_minus_r_, SinCosLanes<kAccuracy>(theta_e_ / 2));
        return EvaluateWith<kAccuracy>(delta, out, [&](const detail::LobeShape<Real>& a, SinCosPair<Real> half) {
          return detail::LobeProduct<kAccuracy>(a, b, half);
        });
      }
      case LobeKind::ClampedCosine: {
        const SinCosPair<Real> peak = SinCosLanes<kAccuracy>(theta_e_);
        const Real scale = r_ * kInvPi<Real>;
        return EvaluateWith<kAccuracy>(delta, out, [&](const detail::LobeShape<Real>& a, SinCosPair<Real> half) {
          Real cos = (half.cos - half.sin) * (half.cos + half.sin) * peak.cos + 2 * half.sin * half.cos * peak.sin;
          return a.template operator()<kAccuracy>(half) * scale * SelectLanes(cos > 0, cos, Real(0));
        });
      }
      case LobeKind::None: break;
    }
    EvaluateWith<kAccuracy>(delta, out, [](const detail::LobeShape<Real>& a, SinCosPair<Real> half) {
      return a.template operator()<kAccuracy>(half);
    });
  }

  Real operator()(Real delta) const { return segment_lobe(delta) * point_lobe(delta); }

  // HenyeyGreenstein(g, -sin theta) with scattering angle x = theta + pi/2 = delta - lower:
  // 1 - cos = 2 sin^2(x/2) and 1 + cos = 2 cos^2(x/2), both exact near their zero.
  Real segment_lobe(Real delta) const {
    Real half = segment_half_angle(delta);
    return segment_lobe(std::sin(half), std::cos(half));
  }
  Real segment_half_angle(Real delta) const { return (delta - lower_) / 2; }
  Real segment_lobe(Real sin_half, Real cos_half) const {
    return HenyeyGreenstein(g_, 2 * Sqr(sin_half), 2 * Sqr(cos_half));
  }

  Real point_lobe(Real delta) const {
    Real phi = delta - theta_e_;
    switch (kind_) {
      case LobeKind::HenyeyGreenstein: {
        Real s2 = Sqr(std::sin(phi / 2));  // 1 -+ r cos(phi), exact near both peaks
        return HenyeyGreenstein(g_point_, one_minus_r_ + 2 * r_ * s2, one_minus_r_ + 2 * r_ * (1 - s2));
      }
      case LobeKind::ClampedCosine: return std::max(r_ * std::cos(phi), Real(0)) * kInvPi<Real>;
      case LobeKind::None: break;
    }
    return 1;
  }

  Real width() const { return width_; }
  Real segment_g() const { return g_; }
  Real point_g() const { return kind_ == LobeKind::HenyeyGreenstein ? g_point_ : Real(0); }
  LobeKind point_kind() const { return kind_; }
  Real r() const { return r_; }  // length of the point-lobe axis projected into the plane
  Real theta_e_offset() const { return theta_e_; }

  // A lobe that is constant in theta only scales the product; fits ignore it.
  bool segment_lobe_flat() const { return g_ == 0; }
  bool point_lobe_flat() const {
    return kind_ == LobeKind::None || r_ == 0 || (kind_ == LobeKind::HenyeyGreenstein && g_point_ == 0);
  }

  // Where each lobe peaks, as an offset. The segment lobe peaks at a pole, on or beyond an
  // endpoint; of the point lobe's peaks modulo 2 pi, the one nearest the interval
  // (detail::NearestPeak; theta_e + pi for g < 0 lies in [-pi, 2 pi]).
  Real segment_peak() const { return g_ > 0 ? lower_ : upper_; }
  Real point_peak() const { return detail::NearestPeak(theta_e_ + (point_g() < 0 ? kPi<Real> : Real(0)), width_); }
  // Where a piecewise-linear fit must have a node, in increasing order: the point lobe's
  // peak when it lies inside the interval (Novák's split). Returns how many.
  int splits(std::array<Real, 2>& out) const {
    Real peak = point_peak();
    if (point_lobe_flat() || !(peak > 0 && peak < width_)) return 0;
    out[0] = peak;
    return 1;
  }
  Real lower_pole() const { return lower_; }  // the offset of theta = -pi/2

  // kShapes false: without the lobes' shapes, which only evaluate() needs (the Cauchy fits).
  template <int kSize, bool kShapes = true>
  struct Lanes;

  // Each lobe's largest value, as a numerator over a denominator: a fit that needs both the
  // value and its reciprocal then divides once for each, side by side.
  PhaseFraction<Real> segment_peak_value() const { return {HenyeyGreensteinPeak(g_), 1}; }
  PhaseFraction<Real> point_peak_value() const {
    if (kind_ == LobeKind::ClampedCosine) return {r_ * kInvPi<Real>, 1};
    if (kind_ == LobeKind::None) return {1, 1};
    return HenyeyGreensteinFraction(std::abs(g_point_), one_minus_r_, 1 + r_);
  }

 private:
  // evaluate()'s loop: product(segment lobe, sin and cos of delta / 2) at every offset.
  template <Accuracy kAccuracy, std::size_t N, typename Product>
  void EvaluateWith(const std::array<Real, N>& delta, std::array<Real, N>& out, Product product) const {
    const auto a = detail::LobeShape<Real>::Of(g_, 1, 0, SinCosLanes<kAccuracy>(lower_ / 2));
    for (std::size_t j = 0; j < N; ++j) out[j] = product(a, SinCosLanes<kAccuracy>(delta[j] / 2));
  }

  Real g_, g_point_;
  LobeKind kind_;
  Real width_;
  Real lower_, upper_;
  Real r_ = 0, one_minus_r_ = 1, theta_e_ = 0;
};

// The targets of a batch's camera steps, one per lane, for fits of all of them at once
// (PiecewiseLinearAngle::SampleLanes, CauchyLobesLanes): the medium-to-medium gathers' queries, a
// Henyey-Greenstein point lobe about each VRL's direction with the segment's g
// (MediumToMediumQuery). Each lane holds what the constructor and evaluate() compute for its
// query, in the same operations (square roots by Newton steps in lanes: within 3 ulp).
template <typename Real>
template <int kSize, bool kShapes>
struct PhaseProduct<Real>::Lanes {
  Real width[kSize], lower[kSize], upper[kSize], theta_e[kSize], r[kSize], one_minus_r[kSize];
  // The two lobes' detail::LobeShape, one array per number (the scale is g's alone).
  Real a_sin[kSize], a_cos[kSize], a_base[kSize], a_slope[kSize];
  Real b_sin[kSize], b_cos[kSize], b_base[kSize], b_slope[kSize];
  Real g = 0, scale = 0;

  // Lanes [0, lanes) from the queries' angle frames and the lobes' axes (one array per
  // coordinate); dir is the camera segment's (sigma_t: unused, FullProductTarget's needs it).
  template <Accuracy kAccuracy>
  void build(const detail::AngleFrameLanes<Real, kSize>& frames, const Real* axis_x, const Real* axis_y, const Real* axis_z,
             Vec3<Real> dir, Real segment_g, Real /*sigma_t*/, int lanes) {
    g = segment_g;
    scale = (1 - g) * (1 + g) / (4 * kPi<Real>);
    for (int i = 0; i < lanes; ++i) {
      const Real A = frames.tan_a[i];
      const detail::PoleOffsets<Real> poles = detail::PolesOf<true>(A);
      const detail::LobeInPlane<Real> lobe = detail::ProjectLobe<true>(
          {axis_x[i], axis_y[i], axis_z[i]}, {frames.nx[i], frames.ny[i], frames.nz[i]}, dir, A, frames.on_line[i] != 0);
      width[i] = frames.width[i], lower[i] = poles.lower, upper[i] = poles.upper;
      theta_e[i] = lobe.theta_e, r[i] = lobe.r, one_minus_r[i] = lobe.one_minus_r;
      if constexpr (!kShapes) continue;
      const auto a = detail::LobeShape<Real>::Of(g, 1, 0, SinCosLanes<kAccuracy>(poles.lower / 2));
      const auto b = detail::LobeShape<Real>::Of(g, lobe.r, lobe.one_minus_r, SinCosLanes<kAccuracy>(lobe.theta_e / 2));
      a_sin[i] = a.from_sin, a_cos[i] = a.from_cos, a_base[i] = a.base, a_slope[i] = a.slope;
      b_sin[i] = b.from_sin, b_cos[i] = b.from_cos, b_base[i] = b.base, b_slope[i] = b.slope;
    }
  }

  // point_lobe_flat() and point_peak() of lane i.
  [[gnu::always_inline]] bool point_lobe_flat(int i) const { return (r[i] == 0) | (g == 0); }
  [[gnu::always_inline]] Real point_peak(int i) const {
    return detail::NearestPeak(theta_e[i] + (g < 0 ? kPi<Real> : Real(0)), width[i]);
  }

  // splits() of each lane: count[i] offsets in split[0][i], ...
  void splits(int lanes, Real (*split)[kSize], int* count) const {
    for (int i = 0; i < lanes; ++i) {
      const Real peak = point_peak(i);
      split[0][i] = peak;
      count[i] = static_cast<int>(!point_lobe_flat(i) & (peak > 0) & (peak < width[i]));
    }
  }

  // evaluate() at delta[i] for every lane i.
  template <Accuracy kAccuracy>
  void evaluate(int lanes, const Real* delta, Real* out) const {
    for (int i = 0; i < lanes; ++i) {
      const detail::LobeShape<Real> a{a_sin[i], a_cos[i], a_base[i], a_slope[i], scale};
      const detail::LobeShape<Real> b{b_sin[i], b_cos[i], b_base[i], b_slope[i], scale};
      out[i] = detail::LobeProduct<kAccuracy>(a, b, SinCosLanes<kAccuracy>(delta[i] / 2));
    }
  }
};

}  // namespace vrlis
