#pragma once
// A minimal 3-vector so that the core needs nothing beyond the standard library.
#include <cmath>

namespace vrlis {

template <typename Real>
struct Vec3 {
  Real x = 0, y = 0, z = 0;
};

template <typename Real>
constexpr Vec3<Real> operator+(Vec3<Real> a, Vec3<Real> b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <typename Real>
constexpr Vec3<Real> operator-(Vec3<Real> a, Vec3<Real> b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <typename Real>
constexpr Vec3<Real> operator-(Vec3<Real> a) { return {-a.x, -a.y, -a.z}; }
template <typename Real>
constexpr Vec3<Real> operator*(Real s, Vec3<Real> a) { return {s * a.x, s * a.y, s * a.z}; }
template <typename Real>
constexpr Real Dot(Vec3<Real> a, Vec3<Real> b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <typename Real>
constexpr Vec3<Real> Cross(Vec3<Real> a, Vec3<Real> b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename Real>
Real Length(Vec3<Real> a) { return std::sqrt(Dot(a, a)); }
template <typename Real>
Vec3<Real> Normalize(Vec3<Real> a) { return (Real(1) / Length(a)) * a; }
template <typename Real>
bool IsFinite(Vec3<Real> a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

// Some unit vector perpendicular to the unit vector n (Duff et al. 2017, "Building an
// orthonormal basis, revisited": branch on the sign of n.z to avoid the singularity).
template <typename Real>
Vec3<Real> AnyPerpendicular(Vec3<Real> n) {
  Real sign = std::copysign(Real(1), n.z);
  Real a = Real(-1) / (sign + n.z);
  return {1 + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x};
}

}  // namespace vrlis
