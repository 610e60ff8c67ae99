#pragma once
// What a camera-segment sampler is asked: a segment, a point, and the two phase lobes
// whose product it should follow.
#include <cmath>
#include <limits>

#include "vec3.hpp"

namespace vrlis {

// The lobe at the point p, as a function of the direction d from p to the segment point.
enum class LobeKind {
  None,              // 1: a point light, or a lobe the caller accounts for itself
  HenyeyGreenstein,  // HenyeyGreenstein(g, dot(axis, d)): a VRL point scattering light that travelled along axis
  ClampedCosine,     // max(0, dot(axis, d)) / pi: a diffuse surface with normal axis
};

template <typename Real>
struct PointLobe {
  LobeKind kind = LobeKind::None;
  Vec3<Real> axis{};  // unit length
  Real g = 0;         // HenyeyGreenstein only
};

// The segment x(t) = origin + t dir, t in [tmin, tmax], seen from the point p. The lobe on
// the segment is HenyeyGreenstein(g, dot(dir, normalize(p - x(t)))): for a camera segment,
// light arriving from p and scattered back towards the camera.
template <typename Real>
struct SegmentQuery {
  Vec3<Real> origin{}, dir{};  // dir unit length
  Real tmin = 0, tmax = 0;     // tmin finite; tmax may be +infinity
  Real g = 0;                  // the segment lobe, |g| < 1
  Vec3<Real> point{};
  PointLobe<Real> lobe{};
  Real sigma_t = 0;  // homogeneous extinction, for samplers that model transmittance
};

// Medium to medium: the camera segment origin + t dir, t in [tmin, tmax], gathering from
// the point vrl_point of a VRL travelling along vrl_dir; both scatter with HG(g).
template <typename Real>
SegmentQuery<Real> MediumToMediumQuery(Vec3<Real> origin, Vec3<Real> dir, Real tmin, Real tmax, Vec3<Real> vrl_point,
                                       Vec3<Real> vrl_dir, Real g, Real sigma_t) {
  return {origin, dir, tmin, tmax, g, vrl_point, {LobeKind::HenyeyGreenstein, vrl_dir, g}, sigma_t};
}

// Medium to surface: the VRL origin + t dir, t in [tmin, tmax], seen from a diffuse surface
// point with unit normal (facing the side the light arrives from); the VRL scatters with HG(g).
template <typename Real>
SegmentQuery<Real> MediumToSurfaceQuery(Vec3<Real> vrl_origin, Vec3<Real> vrl_dir, Real tmin, Real tmax,
                                        Vec3<Real> surface_point, Vec3<Real> normal, Real g, Real sigma_t) {
  return {vrl_origin, vrl_dir, tmin, tmax, g, surface_point, {LobeKind::ClampedCosine, normal, Real(0)}, sigma_t};
}

// A point light seen from the camera segment origin + t dir, t in [tmin, tmax], which
// scatters with HG(g); the light's own lobe is isotropic.
template <typename Real>
SegmentQuery<Real> PointLightQuery(Vec3<Real> origin, Vec3<Real> dir, Real tmin, Real tmax, Vec3<Real> light, Real g,
                                   Real sigma_t) {
  return {origin, dir, tmin, tmax, g, light, {LobeKind::None, {}, Real(0)}, sigma_t};
}

// A sampled parameter along a segment (or a VRL) and its density with respect to it.
template <typename Real>
struct SegmentSample {
  Real t = 0, pdf = 0;
};

// Tag: the caller has validated the query (Validate(q) == QueryError::None), e.g. because
// it derived it from a validated gather query; the sampler skips validating it again.
struct ValidQuery {};

enum class QueryError {
  None,
  NonFinite,          // a NaN or infinity where a finite number is required
  NotUnitDirection,   // a direction whose length differs from 1 by more than 1e-3
  ReversedSegment,    // tmax < tmin
  InvalidAsymmetry,   // |g| >= 1
  NegativeExtinction,
  NegativeScattering,
  ScatteringExceedsExtinction,  // sigma_s > sigma_t: typically (sigma_a, sigma_s) given as (sigma_s, sigma_t)
  OutOfRange,                   // a coordinate beyond MaxCoordinate<Real>(): squared distances would overflow
};
inline constexpr int kQueryErrorCount = static_cast<int>(QueryError::OutOfRange) + 1;

inline const char* Describe(QueryError e) {
  switch (e) {
    case QueryError::None: return "valid";
    case QueryError::NonFinite: return "non-finite input";
    case QueryError::NotUnitDirection: return "direction is not unit length";
    case QueryError::ReversedSegment: return "segment has tmax < tmin";
    case QueryError::InvalidAsymmetry: return "Henyey-Greenstein g outside (-1, 1)";
    case QueryError::NegativeExtinction: return "negative extinction";
    case QueryError::NegativeScattering: return "negative scattering coefficient";
    case QueryError::ScatteringExceedsExtinction:
      return "scattering coefficient above extinction (sigma_t = sigma_a + sigma_s; see Medium's factories)";
    case QueryError::OutOfRange: return "coordinate too large for this floating-point type";
  }
  return "unknown";
}

// Coordinates and segment bounds must stay below this (finite tmax included) so that the
// squared distances the samplers form cannot overflow: about 2e18 in float, 1e153 in double.
template <typename Real>
Real MaxCoordinate() { return std::sqrt(std::numeric_limits<Real>::max()) / 8; }

namespace detail {
template <typename Real>
bool IsUnit(Vec3<Real> v) { return std::abs(Dot(v, v) - 1) <= Real(2e-3); }
template <typename Real>
bool InRange(Vec3<Real> v) {
  Real m = MaxCoordinate<Real>();
  return std::abs(v.x) <= m && std::abs(v.y) <= m && std::abs(v.z) <= m;
}
template <typename Real>
bool IsAsymmetry(Real g) { return std::abs(g) < 1; }  // false for NaN too
}  // namespace detail

template <typename Real>
QueryError Validate(const SegmentQuery<Real>& q) {
  // x * 0 is 0 for finite x and NaN otherwise, so one comparison checks every input.
  Vec3<Real> zeros = Real(0) * (q.origin + q.dir + q.point + q.lobe.axis);
  if (!(zeros.x + zeros.y + zeros.z + 0 * q.tmin + 0 * q.sigma_t == 0) || std::isnan(q.tmax))
    return QueryError::NonFinite;
  if (!detail::IsUnit(q.dir) || (q.lobe.kind != LobeKind::None && !detail::IsUnit(q.lobe.axis)))
    return QueryError::NotUnitDirection;
  if (!(q.tmax >= q.tmin)) return QueryError::ReversedSegment;
  if (!detail::IsAsymmetry(q.g) || (q.lobe.kind == LobeKind::HenyeyGreenstein && !detail::IsAsymmetry(q.lobe.g)))
    return QueryError::InvalidAsymmetry;
  if (q.sigma_t < 0) return QueryError::NegativeExtinction;
  if (!detail::InRange(q.origin) || !detail::InRange(q.point) || std::abs(q.tmin) > MaxCoordinate<Real>() ||
      (std::isfinite(q.tmax) && std::abs(q.tmax) > MaxCoordinate<Real>()))
    return QueryError::OutOfRange;
  return QueryError::None;
}

}  // namespace vrlis
