#pragma once
// Cheap upper bounds of one VRL gather's mean, from the two segments' geometry alone: what the
// effort control predicts a gather's second moment from (docs/maths.md#effort). Each in a
// quick and a tight form, and over eight VRLs at once in vector lanes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "../core/dispatch.hpp"
#include "../core/gather_query.hpp"
#include "../core/lane_math.hpp"
#include "../core/phase.hpp"

namespace vrlis {

namespace detail {
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline Real Min(Real a, Real b) {
  return Pick<kLanes>(a < b, a, b);
}
// The range [lo, hi] of a . (p(s) - o) / |p(s) - o| over p(s) = p0 + s b, s in [s0, s1]
// (|a| = |b| = 1; s1 may be infinite, where the cosine tends to a . b). Along a line the
// cosine has at most one interior extremum, at s* = (alpha delta - beta gamma) / (beta delta
// - alpha) with alpha = a . P, beta = a . b, gamma = P . P, delta = P . b, P = p0 - o.
// Branch-free (every case computed, then picked), so that kLanes loops vectorise.
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline std::pair<Real, Real> CosineRange(Vec3<Real> a, Vec3<Real> o, Vec3<Real> p0, Vec3<Real> b,
                                                               Real s0, Real s1) {
  const Vec3<Real> P = p0 - o;
  const Real alpha = Dot(a, P), beta = Dot(a, b), gamma = Dot(P, P), delta = Dot(P, b);
  auto at = [&](Real s) {
    Real len2 = gamma + 2 * delta * s + s * s;
    return Pick<kLanes>(len2 > 0, (alpha + beta * s) * PickRsqrt<kLanes>(len2), beta);
  };
  const Real first = at(s0), last = Pick<kLanes>(s1 < std::numeric_limits<Real>::infinity(), at(s1), beta);
  Real lo = Min<kLanes>(first, last), hi = Pick<kLanes>(first > last, first, last);
  const Real den = beta * delta - alpha, s = (alpha * delta - beta * gamma) / den;
  const bool interior = (den != 0) & (s > s0) & (s < s1);
  const Real c = at(Pick<kLanes>(interior, s, s0));
  lo = Pick<kLanes>(interior & (c < lo), c, lo);
  hi = Pick<kLanes>(interior & (c > hi), c, hi);
  return {Pick<kLanes>(lo < -1, Real(-1), lo), Pick<kLanes>(hi > 1, Real(1), hi)};
}
// The largest value of a Henyey-Greenstein lobe whose cosine lies in [lo, hi]: it is
// monotone in the cosine, largest at hi for g > 0 and at lo for g < 0.
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline Real PhaseMax(Real g, std::pair<Real, Real> range) {
  return HenyeyGreenstein<kLanes>(g, Pick<kLanes>(g < 0, range.first, range.second));
}
}  // namespace detail

// The camera segment's and the VRL's lines: their distance r, the sine s of the angle
// between them and the VRL's parameter v0 where it comes closest to the camera line.
template <typename Real>
struct ClosestApproach {
  Real r = 0, s = 0, v0 = 0;
};

template <bool kLanes = false, typename Real>
[[gnu::always_inline]] inline ClosestApproach<Real> Closest(const RaySegment<Real>& camera,
                                                            const VrlSegment<Real>& vrl) {
  Vec3<Real> n = Cross(camera.dir, vrl.dir), w0 = vrl.origin - camera.origin;
  ClosestApproach<Real> c;
  c.s = PickSqrt<kLanes>(Dot(n, n));
  Real b = Dot(camera.dir, vrl.dir);
  bool parallel = c.s < Real(1e-4);
  Vec3<Real> off = Cross(w0, camera.dir);
  c.v0 = Pick<kLanes>(parallel, vrl.length / 2, (b * Dot(camera.dir, w0) - Dot(vrl.dir, w0)) / (c.s * c.s));
  Real r = Pick<kLanes>(parallel, PickSqrt<kLanes>(Dot(off, off)), std::abs(Dot(w0, n)) / c.s);
  c.r = Pick<kLanes>(r > Real(1e-6), r, Real(1e-6));
  return c;
}

// A bound of Int Int du dv / |w|^2 over both segments: the smaller of 1 / r^2 over both
// lengths and pi / h(v) integrated along the VRL (h(v) the distance from y(v) to the camera
// line: h(v)^2 = r^2 + s^2 (v - v0)^2, whose integral of 1 / h is (asinh(k (L - v0)) +
// asinh(k v0)) / s with k = s / r, a difference of inverse hyperbolic sines taken without
// cancellation: near-parallel lines put v0 far away).
template <bool kLanes = false, typename Real>
[[gnu::always_inline]] inline Real InverseSquareBound(const RaySegment<Real>& camera, const VrlSegment<Real>& vrl,
                                                      const ClosestApproach<Real>& c) {
  const Real k = c.s / c.r, xa = -k * c.v0, dx = k * vrl.length, xb = xa + dx;
  const Real asinh =
      Log1pLanes(AsinhDifferenceArgument(xa, dx, PickSqrt<kLanes>(1 + xa * xa), PickSqrt<kLanes>(1 + xb * xb)));
  const Real along = Pick<kLanes>(c.s < Real(1e-4), vrl.length / c.r, asinh / c.s);
  return detail::Min<kLanes>((camera.tmax - camera.tmin) * vrl.length / (c.r * c.r), kPi<Real> * along);
}

// A bound of the medium-to-medium gather's mean, Int Int f du dv over both segments (the
// integrand of medium_gather.hpp): 1 / |w|^2 by InverseSquareBound, each phase by its largest
// value over the cosines the two segments allow, and the three legs' transmittance by its value
// at (tmin, 0): the optical length (t - tmin) + v + |x(t) - y(v)| grows with t and with v (a
// distance changes no faster than its end point). The camera phase's cosine d . w / |w|
// (w = y - x) falls as t grows, so it is largest at tmin and smallest at tmax, and the VRL's
// -e . w / |w| falls as v grows: each range is one CosineRange along the other segment.
// Cheap: no sampler. kLanes: branch-free, for MediumGatherBounds.
template <bool kLanes = false, typename Real>
[[gnu::always_inline]] inline Real MediumGatherBound(const RaySegment<Real>& camera, const VrlSegment<Real>& vrl,
                                                     const Medium<Real>& m) {
  const ClosestApproach<Real> c = Closest<kLanes>(camera, vrl);
  const Vec3<Real> x0 = camera.at(camera.tmin), y0 = vrl.origin, y1 = vrl.at(vrl.length);
  const Real camera_length = camera.tmax - camera.tmin;
  const bool bounded = camera_length < std::numeric_limits<Real>::infinity();
  // An unbounded camera segment's cosine falls to -1 at its far end; its start stands in.
  const Vec3<Real> x1 = camera.at(Pick<kLanes>(bounded, camera.tmax, camera.tmin));
  const Real camera_hi = detail::CosineRange<kLanes>(camera.dir, x0, y0, vrl.dir, Real(0), vrl.length).second;
  const Real camera_lo = detail::CosineRange<kLanes>(camera.dir, x1, y0, vrl.dir, Real(0), vrl.length).first;
  const std::pair<Real, Real> camera_cos{Pick<kLanes>(bounded, camera_lo, Real(-1)), camera_hi};
  const std::pair<Real, Real> vrl_cos{
      detail::CosineRange<kLanes>(vrl.dir, y1, x0, camera.dir, Real(0), camera_length).first,
      detail::CosineRange<kLanes>(vrl.dir, y0, x0, camera.dir, Real(0), camera_length).second};
  const Real phases = detail::PhaseMax<kLanes>(m.g, camera_cos) * detail::PhaseMax<kLanes>(m.g, vrl_cos);
  const Vec3<Real> gap = y0 - x0;
  return Sqr(m.sigma_s) * phases * ExpLanes(-m.sigma_t * PickSqrt<kLanes>(Dot(gap, gap))) *
         InverseSquareBound<kLanes>(camera, vrl, c);
}

// MediumGatherBound with both phases by their largest value over all angles and 1 / |w|^2 by
// 1 / r^2 over both lengths or pi / r along the VRL (h(v) >= r): looser, and no inverse
// hyperbolic sine.
template <bool kLanes = false, typename Real>
[[gnu::always_inline]] inline Real MediumGatherQuickBound(const RaySegment<Real>& camera, const VrlSegment<Real>& vrl,
                                                          const Medium<Real>& m) {
  const Vec3<Real> gap = vrl.origin - camera.at(camera.tmin);
  const Real r = Closest<kLanes>(camera, vrl).r;
  const Real peak = HenyeyGreensteinPeak(m.g);  // the lobe's largest value
  return Sqr(m.sigma_s * peak) * ExpLanes(-m.sigma_t * PickSqrt<kLanes>(Dot(gap, gap))) * vrl.length *
         detail::Min<kLanes>((camera.tmax - camera.tmin) / (r * r), kPi<Real> / r);
}

// The VRLs whose bounds MediumGatherBounds and SurfaceGatherBounds take at once: eight float
// lanes (one AVX register).
inline constexpr int kBoundBatch = 8;

namespace detail {
// quick(vrl) into quick[i] and tight(vrl) into tight[i], each if set, for vrls[0, count),
// count <= kBoundBatch: the VRLs in one array per coordinate (the layout vector loads want),
// each bound one loop over lanes (flattened: a bound not inlined keeps its loop scalar); the
// unused lanes repeat the first VRL.
template <typename Real, typename Quick, typename Tight>
[[gnu::flatten]] void BoundLanes(const VrlSegment<Real>* vrls, int count, Real* quick, Real* tight,
                                 Quick&& quick_bound, Tight&& tight_bound) {
  Real ox[kBoundBatch], oy[kBoundBatch], oz[kBoundBatch], dx[kBoundBatch], dy[kBoundBatch], dz[kBoundBatch],
      length[kBoundBatch], out[kBoundBatch];
  for (int i = 0; i < kBoundBatch; ++i) {
    const VrlSegment<Real>& vrl = vrls[i < count ? i : 0];
    ox[i] = vrl.origin.x, oy[i] = vrl.origin.y, oz[i] = vrl.origin.z;
    dx[i] = vrl.dir.x, dy[i] = vrl.dir.y, dz[i] = vrl.dir.z;
    length[i] = vrl.length;
  }
  auto lane = [&](int i) { return VrlSegment<Real>{{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}, length[i]}; };
  if (quick) {
    for (int i = 0; i < kBoundBatch; ++i) out[i] = quick_bound(lane(i));
    for (int i = 0; i < count; ++i) quick[i] = out[i];
  }
  if (tight) {
    for (int i = 0; i < kBoundBatch; ++i) out[i] = tight_bound(lane(i));
    for (int i = 0; i < count; ++i) tight[i] = out[i];
  }
}
}  // namespace detail

// MediumGatherQuickBound into quick[i] and MediumGatherBound into tight[i], each if set, for
// vrls[0, count), count <= kBoundBatch, to rounding (the lanes take square roots by Newton
// steps): one VRL at a time, a call's decisions cost as much as its gathers, and the VRLs are
// independent, so each bound runs as one loop over lanes that compilers vectorise, on the
// widest lanes the processor has (core/dispatch.hpp), as the gathers and their counted work.
template <typename Real>
void MediumGatherBounds(const RaySegment<Real>& camera, const VrlSegment<Real>* vrls, int count, const Medium<Real>& m,
                        Real* quick, Real* tight) {
  detail::WithWidestLanes([&] {
    detail::BoundLanes(vrls, count, quick, tight, [&](const VrlSegment<Real>& vrl) {
      return MediumGatherQuickBound<true>(camera, vrl, m);
    }, [&](const VrlSegment<Real>& vrl) { return MediumGatherBound<true>(camera, vrl, m); });
  });
}

// A bound of the medium-to-surface gather's mean, Int f dv (surface_gather.hpp, without the
// albedo): zero when the whole VRL is behind the surface (then so is the gather; it is still
// taken at the floor's rate), else the phase by its value at the largest cosine -e . w / |w|
// allows (it falls as v grows: the ends give its range), the cosine n . w / |w| by its largest
// value along the VRL, the two legs' transmittance by its value at the VRL's origin
// (v + |y(v) - x| grows with v), times Int dv / |w|^2 itself: |w|^2 = h^2 + (v - v0)^2 (h the
// point's distance from the VRL's line, v0 its foot) integrates to a difference of arctangents.
template <bool kLanes = false, typename Real>
[[gnu::always_inline]] inline Real SurfaceGatherBound(Vec3<Real> point, Vec3<Real> normal, const VrlSegment<Real>& vrl,
                                                      const Medium<Real>& m) {
  const Vec3<Real> w0 = vrl.origin - point, w1 = w0 + vrl.length * vrl.dir, across = Cross(w0, vrl.dir);
  const bool front0 = Dot(normal, w0) > 0, front1 = Dot(normal, w1) > 0, behind = !front0 & !front1;
  const Real h = PickSqrt<kLanes>(Dot(across, across)), v0 = -Dot(vrl.dir, w0);
  const Real hc = Pick<kLanes>(h > Real(1e-6), h, Real(1e-6));
  const Real l0 = PickSqrt<kLanes>(Dot(w0, w0)), l1 = PickSqrt<kLanes>(Dot(w1, w1));
  const std::pair<Real, Real> phase_cos{Pick<kLanes>(l1 > 0, -Dot(vrl.dir, w1) / l1, Real(-1)),
                                        Pick<kLanes>(l0 > 0, -Dot(vrl.dir, w0) / l0, Real(1))};
  const Real cosine = detail::CosineRange<kLanes>(normal, point, vrl.origin, vrl.dir, Real(0), vrl.length).second;
  // atan(y / h) = atan2(y, h) for h > 0
  const Real inverse_square = (Atan2Lanes(vrl.length - v0, hc) + Atan2Lanes(v0, hc)) / hc;
  const Real bound = m.sigma_s * detail::PhaseMax<kLanes>(m.g, phase_cos) * Pick<kLanes>(cosine > 0, cosine, Real(0)) *
                     kInvPi<Real> * ExpLanes(-m.sigma_t * l0) * inverse_square;
  return Pick<kLanes>(behind, Real(0), bound);
}

// SurfaceGatherBound with the phase by its largest value over all angles, the cosine by one
// and Int dv / |w|^2 by min(length / h^2, pi / h): looser, and no arctangent.
template <bool kLanes = false, typename Real>
[[gnu::always_inline]] inline Real SurfaceGatherQuickBound(Vec3<Real> point, Vec3<Real> normal,
                                                           const VrlSegment<Real>& vrl, const Medium<Real>& m) {
  const Vec3<Real> w0 = vrl.origin - point, across = Cross(w0, vrl.dir);
  const bool front0 = Dot(normal, w0) > 0, front1 = Dot(normal, w0 + vrl.length * vrl.dir) > 0;
  const bool behind = !front0 & !front1;
  const Real h = PickSqrt<kLanes>(Dot(across, across)), hc = Pick<kLanes>(h > Real(1e-6), h, Real(1e-6));
  const Real bound = m.sigma_s * HenyeyGreensteinPeak(m.g) * kInvPi<Real> *
                     ExpLanes(-m.sigma_t * PickSqrt<kLanes>(Dot(w0, w0))) *
                     detail::Min<kLanes>(vrl.length / (hc * hc), kPi<Real> / hc);
  return Pick<kLanes>(behind, Real(0), bound);
}

// SurfaceGatherQuickBound into quick[i] and SurfaceGatherBound into tight[i], each if set, for
// vrls[0, count), count <= kBoundBatch, in vector lanes as MediumGatherBounds.
template <typename Real>
void SurfaceGatherBounds(Vec3<Real> point, Vec3<Real> normal, const VrlSegment<Real>* vrls, int count,
                         const Medium<Real>& m, Real* quick, Real* tight) {
  detail::WithWidestLanes([&] {
    detail::BoundLanes(vrls, count, quick, tight, [&](const VrlSegment<Real>& vrl) {
      return SurfaceGatherQuickBound<true>(point, normal, vrl, m);
    }, [&](const VrlSegment<Real>& vrl) { return SurfaceGatherBound<true>(point, normal, vrl, m); });
  });
}
}  // namespace vrlis
