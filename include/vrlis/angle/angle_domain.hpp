#pragma once
// The shared reduction of a query to the angle domain (docs/maths.md#angle-domain).
//
// With u0 the foot of the perpendicular from p and h its length, t - u0 = h tan(theta)
// turns dt / |p - x(t)|^2 into dtheta / h. Samplers work with the offset
// delta = theta - theta_a in [0, width] rather than theta itself: narrow intervals and
// peaks near an endpoint keep all their digits, and tan never sees pi/2.
#include <cstdint>
#include <limits>

#include "../core/math.hpp"
#include "../core/query.hpp"
#include "../core/lane_math.hpp"

namespace vrlis {

// A point of the segment at an angle offset: its parameter t and the Jacobian dtheta/dt.
template <typename Real>
struct AnglePoint {
  Real t = 0, dtheta_dt = 0;
};

namespace detail {

// The reduction's numbers for one point p (AngleDomain's members).
template <typename Real>
struct AngleFrame {
  Real u0, h, tan_a, stretch, width;
  Vec3<Real> n;
  bool on_line;
};

// The frames of a batch's queries, one array per number: the layout vector loads and stores
// want, so that loops over the batch (ReduceToAngles<true>, PointAtOffset<true>) vectorise.
template <typename Real, int kSize>
struct AngleFrameLanes {
  Real u0[kSize], h[kSize], tan_a[kSize], stretch[kSize], width[kSize], nx[kSize], ny[kSize], nz[kSize];
  std::int32_t on_line[kSize];  // (as wide as the floats: a loop that mixes bytes with them stays scalar)

  void set(int i, const AngleFrame<Real>& f) {
    u0[i] = f.u0, h[i] = f.h, tan_a[i] = f.tan_a, stretch[i] = f.stretch, width[i] = f.width;
    nx[i] = f.n.x, ny[i] = f.n.y, nz[i] = f.n.z, on_line[i] = f.on_line ? 1 : 0;
  }
  AngleFrame<Real> operator[](int i) const {
    return {u0[i], h[i], tan_a[i], stretch[i], width[i], {nx[i], ny[i], nz[i]}, on_line[i] != 0};
  }
};

// atan(b) - atan(a) with b - a = db >= 0 and tan_a = a, from the argument of (1 + i b)(1 - i a).
template <typename Real>
[[gnu::always_inline]] inline Real OffsetOfSlope(Real tan_a, Real db, Real b) {
  return Atan2Lanes(db, 1 + tan_a * b);
}

// With kLanes branch-free (every case computed, then picked), so that a loop over points
// (VrlMarginal's nodes) vectorises; otherwise each case is computed only where taken.
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline AngleFrame<Real> ReduceToAngles(const Vec3<Real>& point, const Vec3<Real>& origin,
                                                              const Vec3<Real>& dir, Real tmin, Real tmax) {
  AngleFrame<Real> f;
  Vec3<Real> d = point - origin;
  f.u0 = Dot(d, dir);
  Vec3<Real> perp = d - f.u0 * dir;
  Real h = PickSqrt<kLanes>(Dot(perp, perp));
  bool bounded = std::abs(tmax) < std::numeric_limits<Real>::infinity();
  Real scale = std::abs(d.x) + std::abs(d.y) + std::abs(d.z) + std::abs(tmin) + Pick<kLanes>(bounded, std::abs(tmax), Real(0));
  Real floor = NoiseFloor(scale);
  // On (or within rounding of) the line the plane is arbitrary; any normal will do.
  f.on_line = !(h > floor);
  Real inv_h = Real(1) / h;
  if constexpr (kLanes) {
    Vec3<Real> any = AnyPerpendicular(dir);
    f.n = {SelectLanes(f.on_line, any.x, inv_h * perp.x), SelectLanes(f.on_line, any.y, inv_h * perp.y),
           SelectLanes(f.on_line, any.z, inv_h * perp.z)};
  } else {
    f.n = f.on_line ? AnyPerpendicular(dir) : inv_h * perp;
  }
  f.h = h = Pick<kLanes>(h < floor, floor, h);
  f.tan_a = (tmin - f.u0) / h;
  f.stretch = h + (tmin - f.u0) * f.tan_a;  // h (1 + A^2), from two non-negative terms
  // OffsetOfSlope's two arguments times h (an arctangent of a ratio does not see the common
  // factor): the slopes' two divisions are off the chain every fit waits on.
  if constexpr (kLanes) {
    f.width = SelectLanes(bounded, Atan2Lanes(tmax - tmin, h + f.tan_a * (tmax - f.u0)), Atan2Lanes(Real(1), f.tan_a));
  } else {
    f.width = bounded ? Atan2Lanes(tmax - tmin, h + f.tan_a * (tmax - f.u0)) : Atan2Lanes(Real(1), f.tan_a);
  }
  return f;
}

// dtheta / dt = h / (h^2 + (t - u0)^2).
template <typename Real>
[[gnu::always_inline]] inline Real DthetaDt(Real t, Real u0, Real h) {
  Real x = (t - u0) / h;
  return Real(1) / (h * (1 + x * x));
}

// The point at the angle offset delta of the frame f over [tmin, tmax], and dtheta/dt there,
// from the sine and cosine that carry delta to t: with
// denom = cos(delta) - tan(theta_a) sin(delta) = cos(theta) / cos(theta_a),
// t = tmin + h (1 + A^2) sin(delta) / denom and dtheta/dt = cos^2(theta) / h = denom^2 / (h (1 + A^2)).
// This equals DthetaDt of the rounded t to a few ulps (tan of the computed t's angle is
// (A c + s) / denom). A t past the largest finite sample (tmax, or the largest Real on an
// unbounded segment) is clamped to it and takes its density there; so does a step that
// rounds to nothing, at tmin (h (1 + A^2) may overflow; never multiply it by 0). kLanes:
// branch-free, with SinCosLanes, for a loop over a batch's domains.
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline AnglePoint<Real> PointAtOffset(const AngleFrame<Real>& f, Real tmin, Real tmax,
                                                             Real delta) {
  constexpr Real kInf = std::numeric_limits<Real>::infinity();
  SinCosPair<Real> sc = kLanes ? SinCosLanes(delta) : SinCos(delta);
  Real s = sc.sin, c = sc.cos;
  Real denom = c - f.tan_a * s;  // cos(theta) / cos(theta_a) > 0 inside the domain
  const Real largest = std::abs(tmax) < kInf ? tmax : std::numeric_limits<Real>::max();
  if constexpr (kLanes) {
    Real step = SelectLanes(denom > 0, s / denom, kInf);
    Real t = tmin + f.stretch * step;
    bool at_tmin = !(step > 0), clamped = at_tmin | !(t < largest);
    Real end = SelectLanes(at_tmin, tmin, largest);
    return {SelectLanes(clamped, end, SelectLanes(t > tmin, t, tmin)),
            SelectLanes(clamped, DthetaDt(end, f.u0, f.h), denom * denom / f.stretch)};
  } else {
    Real step = denom > 0 ? s / denom : kInf;
    if (!(step > 0)) return {tmin, DthetaDt(tmin, f.u0, f.h)};
    Real t = tmin + f.stretch * step;
    if (!(t < largest)) return {largest, DthetaDt(largest, f.u0, f.h)};
    return {std::max(t, tmin), denom * denom / f.stretch};
  }
}

}  // namespace detail

template <typename Real>
class AngleDomain {
 public:
  explicit AngleDomain(const SegmentQuery<Real>& q)
      : AngleDomain(q, detail::ReduceToAngles<false>(q.point, q.origin, q.dir, q.tmin, q.tmax)) {}
  // From q's reduction computed elsewhere: detail::ReduceToAngles<true> of its point, which a
  // batch runs in lanes over many points against one segment.
  AngleDomain(const SegmentQuery<Real>& q, const detail::AngleFrame<Real>& f)
      : tmin_(q.tmin), tmax_(q.tmax), u0_(f.u0), h_(f.h), tan_a_(f.tan_a), stretch_(f.stretch), width_(f.width),
        n_(f.n), on_line_(f.on_line) {}

  Real tmin() const { return tmin_; }
  Real tmax() const { return tmax_; }
  Real u0() const { return u0_; }
  Real h() const { return h_; }
  Vec3<Real> normal() const { return n_; }  // unit, from the foot of the perpendicular to p
  // p lies on the segment's line up to rounding: h is the noise floor and normal() arbitrary.
  bool on_line() const { return on_line_; }
  Real tan_theta_a() const { return tan_a_; }
  Real theta_a() const { return std::atan(tan_a_); }
  Real theta_b() const { return theta_a() + width_; }
  Real width() const { return width_; }  // theta_b - theta_a, computed without cancellation

  // theta(t) - theta_a for t in [tmin, tmax].
  Real offset_at(Real t) const {
    if (!(t < tmax_)) return width_;
    if (!(t > tmin_)) return 0;
    Real db = (t - tmin_) / h_, b = (t - u0_) / h_;
    // Beyond h * max<Real> the remaining angle atan(h / (t - u0)) is below 1 / max<Real>.
    if (!std::isfinite(db) || !std::isfinite(b)) return width_;
    return detail::OffsetOfSlope(tan_a_, db, b);
  }

  // The inverse of offset_at: tan(theta_a + delta) written with the addition formula.
  Real t_at(Real delta) const { return point_at(delta).t; }

  // t_at(delta) and dtheta/dt there (detail::PointAtOffset).
  AnglePoint<Real> point_at(Real delta) const {
    return detail::PointAtOffset<false>(frame(), tmin_, tmax_, delta);
  }

  // dtheta / dt = h / (h^2 + (t - u0)^2).
  Real dtheta_dt(Real t) const { return detail::DthetaDt(t, u0_, h_); }

 private:
  detail::AngleFrame<Real> frame() const { return {u0_, h_, tan_a_, stretch_, width_, n_, on_line_}; }

  Real tmin_, tmax_, u0_, h_, tan_a_, stretch_, width_;
  Vec3<Real> n_;
  bool on_line_;
};

}  // namespace vrlis
