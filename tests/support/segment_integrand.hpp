#pragma once
// The integrand of a SegmentQuery written directly from 3D vectors in double, independent
// of the library's maths (AngleDomain, PhaseProduct, phase.hpp): a reference should fail
// differently. Standard library only (the fuzz target includes it too).
#include <algorithm>
#include <cmath>
#include <limits>

#include <vrlis/vrlis.hpp>

namespace vrlis::stability {

using V3 = vrlis::Vec3<double>;
constexpr double kPi = 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

inline V3 ToDouble(const vrlis::Vec3<float>& v) { return {v.x, v.y, v.z}; }
inline V3 ToDouble(const vrlis::Vec3<double>& v) { return v; }
inline double Len(V3 v) { return std::sqrt(vrlis::Dot(v, v)); }
inline V3 Unit(V3 v) { return (1 / Len(v)) * v; }

// Henyey-Greenstein from the two unit vectors whose dot product is the cosine:
// 1 - cos = |a - b|^2 / 2 and 1 + cos = |a + b|^2 / 2 keep their digits near both peaks.
inline double HG(double g, V3 a, V3 b) {
  V3 dm = a - b, dp = a + b;
  double one_minus = vrlis::Dot(dm, dm) / 2, one_plus = vrlis::Dot(dp, dp) / 2;
  double denom = g >= 0 ? (1 - g) * (1 - g) + 2 * g * one_minus : (1 + g) * (1 + g) + 2 * -g * one_plus;
  return (1 - g) * (1 + g) / (4 * kPi * denom * std::sqrt(denom));
}

// A query converted to double, with the directions renormalised (the library takes
// them as unit; so does the reference, to the last digit).
struct RefQuery {
  V3 origin, dir, point, axis;
  double tmin, tmax, g, lobe_g;
  vrlis::LobeKind kind;
  // Treat a clamped cosine below this as zero (the contract's positivity check exempts the
  // rounding noise at the lobe's kink).
  double clamp_margin = 0;

  template <typename Real>
  explicit RefQuery(const vrlis::SegmentQuery<Real>& q)
      : origin(ToDouble(q.origin)),
        dir(Unit(ToDouble(q.dir))),
        point(ToDouble(q.point)),
        axis(q.lobe.kind == vrlis::LobeKind::None ? V3{} : Unit(ToDouble(q.lobe.axis))),
        tmin(q.tmin),
        tmax(q.tmax),
        g(q.g),
        lobe_g(q.lobe.g),
        kind(q.lobe.kind) {}

  // The product of the two lobes for e = the unit direction from the segment point to p.
  double Lobes(V3 e) const {
    double seg = HG(g, dir, e);
    switch (kind) {
      case vrlis::LobeKind::HenyeyGreenstein: return seg * HG(lobe_g, axis, -1.0 * e);
      case vrlis::LobeKind::ClampedCosine: {
        double c = -vrlis::Dot(axis, e);
        return c > clamp_margin ? seg * c / kPi : 0.0;
      }
      case vrlis::LobeKind::None: break;
    }
    return seg;
  }

  // The integrand at t, from 3D vectors: lobes / |p - x(t)|^2.
  double f(double t) const {
    V3 x = origin + t * dir;
    V3 v = point - x;
    double d2 = vrlis::Dot(v, v);
    if (!(d2 > 0)) return kInf;
    if (!std::isfinite(d2)) return 0;
    return Lobes((1 / std::sqrt(d2)) * v) / d2;
  }

  // The perpendicular foot u0, distance h and unit normal n (towards p).
  double u0() const { return vrlis::Dot(point - origin, dir); }
  double h() const {
    V3 d = point - origin;
    return Len(d - u0() * dir);
  }
  V3 n() const {
    V3 d = point - origin;
    return Unit(d - u0() * dir);
  }
  // t(theta) = u0 + h tan(theta).
  double t_of(double theta) const { return u0() + h() * std::tan(theta); }
  double theta_of(double t) const { return std::atan2(t - u0(), h()); }

  // Equiangular sampling's density at t, in long double (whose range does not underflow
  // where float's and double's do): the natural scale of every sampler's density. 0 when p
  // is on the line.
  long double EquiangularDensity(double t) const {
    long double hh = h(), u = u0();
    if (!(hh > 0)) return 0;
    long double width = (std::isfinite(tmax) ? std::atan2((long double)tmax - u, hh) : 1.5707963267948966192L) -
                        std::atan2((long double)tmin - u, hh);
    long double x = ((long double)t - u) / hh;
    return 1 / (hh * (1 + x * x) * width);
  }
};

}  // namespace vrlis::stability
