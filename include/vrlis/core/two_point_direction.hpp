#pragma once
// Directions from a point a for light scattered once on the way from a point light b
// (docs/maths.md#two-point). Along the ray a + t w the inverse squared distances to a and b
// integrate to
//   Int_0^inf t^2 dt / (t^2 |a + t w - b|^2) = (pi - alpha) / (D sin alpha),
// alpha the angle between w and b - a, D = |b - a|. A direction sampled by a phase function or
// a cosine keeps the 1 / sin alpha, whose second moment over directions diverges (Georgiev et
// al. 2013); the density below is proportional to it, so that a direction from it followed by
// an equiangular distance about b weighs at most pi^3 / D:
//   p(w) = (pi - alpha) / (pi^3 sin alpha)   over solid angle,
//   p(alpha) = 2 (pi - alpha) / pi^2         over alpha in [0, pi], phi uniform.
#include <utility>

#include "math.hpp"
#include "vec3.hpp"

namespace vrlis {

template <typename Real>
Real SampleTwoPointAngle(Real u) {
  return kPi<Real> * (1 - std::sqrt(Clamp(1 - u, Real(0), Real(1))));
}

template <typename Real>
Real TwoPointAnglePdf(Real alpha) {
  if (!(alpha >= 0 && alpha <= kPi<Real>)) return 0;
  return 2 * (kPi<Real> - alpha) / Sqr(kPi<Real>);
}

template <typename Real>
Real InvertTwoPointAngle(Real alpha) {
  return 1 - Sqr(1 - Clamp(alpha / kPi<Real>, Real(0), Real(1)));
}

// The direction for (u1, u2): alpha from u1, the azimuth 2 pi u2 about the unit `axis` (b - a).
template <typename Real>
Vec3<Real> SampleTwoPointDirection(Vec3<Real> axis, Real u1, Real u2) {
  Real alpha = SampleTwoPointAngle(u1), phi = 2 * kPi<Real> * u2;
  Vec3<Real> x = AnyPerpendicular(axis), y = Cross(axis, x);
  Real s = std::sin(alpha);
  return (s * std::cos(phi)) * x + (s * std::sin(phi)) * y + std::cos(alpha) * axis;
}

// The angle between unit vectors, accurate at both ends (atan2 of |cross| and dot).
template <typename Real>
Real AngleBetween(Vec3<Real> a, Vec3<Real> b) {
  return std::atan2(Length(Cross(a, b)), Dot(a, b));
}

// Over solid angle; infinite exactly along the axis (an integrable singularity).
template <typename Real>
Real TwoPointDirectionPdf(Vec3<Real> axis, Vec3<Real> w) {
  Real alpha = AngleBetween(axis, w), s = std::sin(alpha);
  if (!(s > 0)) return alpha < 1 ? std::numeric_limits<Real>::infinity() : Real(0);
  return (kPi<Real> - alpha) / (kPi<Real> * Sqr(kPi<Real>) * s);
}

// (u1, u2) with SampleTwoPointDirection(axis, u1, u2) == w.
template <typename Real>
std::pair<Real, Real> InvertTwoPointDirection(Vec3<Real> axis, Vec3<Real> w) {
  Vec3<Real> x = AnyPerpendicular(axis), y = Cross(axis, x);
  Real phi = std::atan2(Dot(w, y), Dot(w, x));
  if (phi < 0) phi += 2 * kPi<Real>;
  return {InvertTwoPointAngle(AngleBetween(axis, w)), phi / (2 * kPi<Real>)};
}

}  // namespace vrlis
