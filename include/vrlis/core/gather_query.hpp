#pragma once
// What a renderer asks of a VRL gather (docs/maths.md#estimators): one camera segment (or
// one surface point, or one point light) against one VRL, in a homogeneous medium. These
// three queries are the library's one model of a gather configuration; the samplers' own
// queries (SegmentQuery, VrlPointQuery) are built from them.
#include "query.hpp"
#include "query_rejections.hpp"

namespace vrlis {

// A ray segment x(t) = origin + t dir, t in [tmin, tmax]; tmax may be +infinity.
template <typename Real>
struct RaySegment {
  Vec3<Real> origin{}, dir{};  // dir unit length
  Real tmin = 0, tmax = 0;
  Vec3<Real> at(Real t) const { return origin + t * dir; }
};

// A virtual ray light y(v) = origin + v dir, v in [0, length] (finite), carrying light that
// travels along dir.
template <typename Real>
struct VrlSegment {
  Vec3<Real> origin{}, dir{};  // dir unit length
  Real length = 0;
  Vec3<Real> at(Real v) const { return origin + v * dir; }
};

// The same VRL: a batch's split samples of one gather share its fits (gather/*_gather.hpp).
template <typename Real>
bool SameVrl(const VrlSegment<Real>& a, const VrlSegment<Real>& b) {
  return a.length == b.length && a.origin.x == b.origin.x && a.origin.y == b.origin.y && a.origin.z == b.origin.z &&
         a.dir.x == b.dir.x && a.dir.y == b.dir.y && a.dir.z == b.dir.z;
}

// A homogeneous medium: Henyey-Greenstein asymmetry, scattering and extinction coefficients.
// Built by name only: renderers store (sigma_a, sigma_s) or (sigma_s, sigma_t), and a
// positional {g, sigma_a, sigma_s} was a valid medium with the wrong extinction; it no longer
// compiles. Default: g = 0 and no medium (every coefficient 0).
template <typename Real>
struct Medium {
  Real g = 0, sigma_s = 0, sigma_t = 0;

  Medium() noexcept {}  // user-provided: not an aggregate, so no positional braces
  static Medium FromAbsorptionScattering(Real g, Real sigma_a, Real sigma_s) {
    return Medium(g, sigma_s, sigma_a + sigma_s);
  }
  static Medium FromScatteringExtinction(Real g, Real sigma_s, Real sigma_t) { return Medium(g, sigma_s, sigma_t); }

 private:
  Medium(Real g_, Real sigma_s_, Real sigma_t_) noexcept : g(g_), sigma_s(sigma_s_), sigma_t(sigma_t_) {}
};

// Medium to medium: light scattered at a VRL point, again at a camera-segment point, then
// carried to the segment's origin.
template <typename Real>
struct MediumGatherQuery {
  RaySegment<Real> camera;
  VrlSegment<Real> vrl;
  Medium<Real> medium;
};

// Medium to surface: light scattered at a VRL point and reflected by a diffuse (Lambertian)
// surface point whose unit normal faces the side the light arrives from.
template <typename Real>
struct SurfaceGatherQuery {
  Vec3<Real> point{}, normal{};
  VrlSegment<Real> vrl;
  Medium<Real> medium;
};

// Single scattering: light from an isotropic point light scattered once on the camera segment.
template <typename Real>
struct PointLightGatherQuery {
  RaySegment<Real> camera;
  Vec3<Real> light{};
  Medium<Real> medium;
};

namespace detail {
// x * 0 is 0 for finite x and NaN otherwise: one comparison checks every input.
template <typename Real>
Real ZeroIfFinite(Vec3<Real> v) { return Real(0) * (v.x + v.y + v.z); }
template <typename Real>
Real ZeroIfFinite(Real x) { return Real(0) * x; }
template <typename... Values>
bool AllFinite(Values... values) { return (ZeroIfFinite(values) + ...) == 0; }
template <typename Real>
QueryError ValidateMedium(const Medium<Real>& m) {
  if (!IsAsymmetry(m.g)) return QueryError::InvalidAsymmetry;
  if (!(m.sigma_t >= 0)) return QueryError::NegativeExtinction;
  if (!(m.sigma_s >= 0)) return QueryError::NegativeScattering;
  if (!(m.sigma_s <= m.sigma_t)) return QueryError::ScatteringExceedsExtinction;
  return QueryError::None;
}
template <typename Real>
QueryError ValidateSegment(const RaySegment<Real>& s) {
  if (!(s.tmax >= s.tmin)) return QueryError::ReversedSegment;
  if (!IsUnit(s.dir)) return QueryError::NotUnitDirection;
  if (!InRange(s.origin) || std::abs(s.tmin) > MaxCoordinate<Real>() ||
      (std::isfinite(s.tmax) && std::abs(s.tmax) > MaxCoordinate<Real>()))
    return QueryError::OutOfRange;
  return QueryError::None;
}
template <typename Real>
QueryError ValidateVrl(const VrlSegment<Real>& v) {
  if (!(v.length >= 0)) return QueryError::ReversedSegment;
  if (!IsUnit(v.dir)) return QueryError::NotUnitDirection;
  if (!InRange(v.origin) || v.length > MaxCoordinate<Real>()) return QueryError::OutOfRange;
  return QueryError::None;
}
}  // namespace detail

// The parts of a gather query on their own, finiteness included. A medium-to-medium query
// is valid exactly when its camera segment, VRL and medium are: a renderer validates a
// camera segment once for all the VRLs it gathers, not once per gather. Every error these
// return is counted (query_rejections.hpp).
template <typename Real>
QueryError Validate(const RaySegment<Real>& s) {
  if (!detail::AllFinite(s.origin, s.dir, s.tmin) || std::isnan(s.tmax)) return detail::Counted(QueryError::NonFinite);
  return detail::Counted(detail::ValidateSegment(s));
}

template <typename Real>
QueryError Validate(const VrlSegment<Real>& v) {
  if (!detail::AllFinite(v.origin, v.dir, v.length)) return detail::Counted(QueryError::NonFinite);
  return detail::Counted(detail::ValidateVrl(v));
}

template <typename Real>
QueryError Validate(const Medium<Real>& m) {
  if (!detail::AllFinite(m.g, m.sigma_s, m.sigma_t)) return detail::Counted(QueryError::NonFinite);
  return detail::Counted(detail::ValidateMedium(m));
}

// The surface point of a medium-to-surface query on its own: a query is valid exactly when
// its point, its VRL and its medium are.
template <typename Real>
QueryError ValidateSurfacePoint(Vec3<Real> point, Vec3<Real> normal) {
  if (!detail::AllFinite(point, normal)) return detail::Counted(QueryError::NonFinite);
  if (!detail::IsUnit(normal)) return detail::Counted(QueryError::NotUnitDirection);
  if (!detail::InRange(point)) return detail::Counted(QueryError::OutOfRange);
  return QueryError::None;
}

template <typename Real>
QueryError Validate(const MediumGatherQuery<Real>& q) {
  const auto& c = q.camera;
  const auto& v = q.vrl;
  if (!detail::AllFinite(c.origin, c.dir, v.origin, v.dir, c.tmin, v.length, q.medium.g, q.medium.sigma_s,
                         q.medium.sigma_t) ||
      std::isnan(c.tmax))
    return detail::Counted(QueryError::NonFinite);
  if (QueryError e = detail::ValidateSegment(c); e != QueryError::None) return detail::Counted(e);
  if (QueryError e = detail::ValidateVrl(v); e != QueryError::None) return detail::Counted(e);
  return detail::Counted(detail::ValidateMedium(q.medium));
}

template <typename Real>
QueryError Validate(const SurfaceGatherQuery<Real>& q) {
  const auto& v = q.vrl;
  if (!detail::AllFinite(q.point, q.normal, v.origin, v.dir, v.length, q.medium.g, q.medium.sigma_s, q.medium.sigma_t))
    return detail::Counted(QueryError::NonFinite);
  if (!detail::IsUnit(q.normal)) return detail::Counted(QueryError::NotUnitDirection);
  if (!detail::InRange(q.point)) return detail::Counted(QueryError::OutOfRange);
  if (QueryError e = detail::ValidateVrl(v); e != QueryError::None) return detail::Counted(e);
  return detail::Counted(detail::ValidateMedium(q.medium));
}

template <typename Real>
QueryError Validate(const PointLightGatherQuery<Real>& q) {
  const auto& c = q.camera;
  if (!detail::AllFinite(c.origin, c.dir, q.light, c.tmin, q.medium.g, q.medium.sigma_s, q.medium.sigma_t) ||
      std::isnan(c.tmax))
    return detail::Counted(QueryError::NonFinite);
  if (!detail::InRange(q.light)) return detail::Counted(QueryError::OutOfRange);
  if (QueryError e = detail::ValidateSegment(c); e != QueryError::None) return detail::Counted(e);
  return detail::Counted(detail::ValidateMedium(q.medium));
}

}  // namespace vrlis
