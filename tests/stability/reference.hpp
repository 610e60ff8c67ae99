#pragma once
// An independent reference for the adversarial suite, the stability table and (without the
// quadrature) the fuzz target: the integrand of a SegmentQuery written directly from 3D
// vectors in double, its integral by adaptive Gauss-Kronrod quadrature in the angle
// variable, the target of VrlPoint, and the library of hard cases.
//
// Nothing here calls the library's maths (AngleDomain, PhaseProduct, phase.hpp): the
// point of a reference is that it fails differently.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "segment_integrand.hpp"

namespace vrlis::stability {

// The integral of f over [tmin, tmax] in the angle variable: f dt = F(theta) dtheta / h with
// F(theta) = Lobes(cos(theta) n - sin(theta) dir). Split at every place a lobe peaks or
// kinks, with nested neighbourhoods so that spikes of width 1 - |g| are resolved. Returns
// +inf when p lies on the segment (the integral diverges), NaN when it cannot tell.
inline double Integral(const RefQuery& q, double* error_estimate = nullptr) {
  double h = q.h();
  if (!(q.tmax > q.tmin)) return 0;
  if (!(h > 0)) {
    double u0 = q.u0();
    if (u0 >= q.tmin && u0 <= q.tmax) return kInf;
    // On the line outside the segment: integrate in t directly (a smooth integrand).
    auto ft = [&](double t) { return q.f(t); };
    double hi = std::isfinite(q.tmax) ? q.tmax : kInf;
    return boost::math::quadrature::gauss_kronrod<double, 61>::integrate(ft, q.tmin, hi, 12, 1e-10);
  }
  V3 n = q.n();
  double ta = q.theta_of(q.tmin), tb = std::isfinite(q.tmax) ? q.theta_of(q.tmax) : kPi / 2;
  auto F = [&](double theta) { return q.Lobes(std::cos(theta) * n - std::sin(theta) * q.dir); };
  std::vector<double> cuts = {ta, tb};
  std::vector<double> centres = {-kPi / 2, kPi / 2};
  if (q.kind != vrlis::LobeKind::None) {
    // The point lobe's axis in the plane: its peak where -e is along the projection.
    double a_d = vrlis::Dot(q.axis, q.dir), a_n = vrlis::Dot(q.axis, n);
    if (a_d != 0 || a_n != 0) {
      double theta_e = std::atan2(a_d, -a_n);
      for (int k = -4; k <= 4; ++k) centres.push_back(theta_e + k * kPi / 2);
    }
  }
  for (double c : centres) {
    cuts.push_back(c);
    for (double w : {1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1}) {
      cuts.push_back(c - w);
      cuts.push_back(c + w);
    }
  }
  std::sort(cuts.begin(), cuts.end());
  double sum = 0, err = 0;
  double prev = ta;
  for (double c : cuts) {
    if (!(c > prev) || c > tb) continue;
    double e = 0;
    sum += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(F, prev, c, 10, 1e-10, &e);
    err += e;
    prev = c;
  }
  if (error_estimate) *error_estimate = err / h;
  return sum / h;
}

// ---------------------------------------------------------------------------------------
// VrlPoint's target: the inverse distance from y(v) to the camera line.
template <typename Real>
struct RefVrlQuery {
  V3 origin, dir, line_origin, line_dir;
  double tmin, tmax;
  explicit RefVrlQuery(const vrlis::VrlPointQuery<Real>& q)
      : origin(ToDouble(q.origin)),
        dir(Unit(ToDouble(q.dir))),
        line_origin(ToDouble(q.line_origin)),
        line_dir(Unit(ToDouble(q.line_dir))),
        tmin(q.tmin),
        tmax(q.tmax) {}
  double f(double v) const {
    V3 w = origin + v * dir - line_origin;
    V3 perp = w - vrlis::Dot(w, line_dir) * line_dir;
    double d = Len(perp);
    return d > 0 ? 1 / d : kInf;
  }
  double Integral() const {
    if (!(tmax > tmin)) return 0;
    auto ff = [&](double v) { return f(v); };
    // Split at the closest approach to the line, where the target peaks.
    V3 d = line_origin - origin, c = vrlis::Cross(dir, line_dir);
    double s2 = vrlis::Dot(c, c);
    std::vector<double> cuts = {tmin, tmax};
    if (s2 > 0) {
      double v0 = (vrlis::Dot(d, dir) - vrlis::Dot(d, line_dir) * vrlis::Dot(dir, line_dir)) / s2;
      for (double w : {0.0, 1e-9, 1e-6, 1e-3, 1.0})
        for (double s : {-1.0, 1.0}) cuts.push_back(v0 + s * w * std::max(1.0, std::abs(v0)));
    }
    std::sort(cuts.begin(), cuts.end());
    double sum = 0, prev = tmin;
    for (double c2 : cuts) {
      if (!(c2 > prev) || c2 > tmax) continue;
      sum += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(ff, prev, c2, 10, 1e-10);
      prev = c2;
    }
    return sum;
  }
};

// ---------------------------------------------------------------------------------------
// The hard cases. Geometry is written in double; the float run uses the same numbers
// rounded to float, and the double run uses that rounded query too, so float-versus-double
// differences come from arithmetic only.
struct HardCase {
  std::string name;
  vrlis::SegmentQuery<double> q;
  bool integrable = true;  // false when p lies on the segment (the integral diverges)
};

// The base geometry: the segment along +x through the origin, p at distance 1 above its
// start (u0 = 0, n = +y), t in [-1, 3], both lobes HG(g) with the point lobe's peak at the
// angle theta_p (the axis lies in the plane: r = 1).
inline vrlis::SegmentQuery<double> Base(double g, double theta_p = 0.3) {
  vrlis::SegmentQuery<double> q;
  q.origin = {0, 0, 0};
  q.dir = {1, 0, 0};
  q.tmin = -1;
  q.tmax = 3;
  q.g = g;
  q.point = {0, 1, 0};
  // dir(p -> x(theta)) = -(cos theta n - sin theta dir) = (sin theta, -cos theta, 0).
  q.lobe = {vrlis::LobeKind::HenyeyGreenstein, {std::sin(theta_p), -std::cos(theta_p), 0}, g};
  return q;
}

// The angle of t seen from p in the base geometry.
inline double BaseTheta(double t) { return std::atan(t); }

inline std::vector<HardCase> HardCases() {
  std::vector<HardCase> cs;
  auto add = [&](std::string name, vrlis::SegmentQuery<double> q, bool integrable = true) {
    cs.push_back({std::move(name), q, integrable});
  };
  add("g=0.9 (reference case)", Base(0.9));
  add("g=+0.999", Base(0.999));
  add("g=-0.999", Base(-0.999));
  add("g=+1e-4", Base(1e-4));
  add("g=-1e-4", Base(-1e-4));
  add("g=0", Base(0));
  {
    auto q = Base(0.999);
    q.lobe.g = -0.999;
    add("g=+0.999, point lobe -0.999", q);
  }
  {
    auto q = Base(0.9);
    q.point = {-2, 0, 0};
    add("p on the line, outside", q);
  }
  {
    auto q = Base(0.9);
    q.point = {1, 0, 0};
    add("p on the segment", q, false);
  }
  {
    auto q = Base(0.9);
    q.point = {1, 1e-7, 0};
    add("p 1e-7 off the line", q);
  }
  {
    auto q = Base(0.999);
    q.point = {1, 1e-7, 0};
    add("p 1e-7 off the line, g=0.999", q);
  }
  {
    auto q = Base(0.9);
    q.tmin = q.tmax = 0.5;
    add("length 0", q);
  }
  {
    auto q = Base(0.9);
    q.tmin = 0.5;
    q.tmax = 0.5 + 1e-6;
    add("length 1e-6", q);
  }
  {
    auto q = Base(0.9);
    q.tmin = 0;
    q.tmax = 1e6;
    add("length 1e6", q);
  }
  {
    auto q = Base(0.9);
    q.tmin = -1;
    q.tmax = kInf;
    add("unbounded, g=0.9", q);
  }
  {
    auto q = Base(-0.999);
    q.tmin = -1e3;
    q.tmax = kInf;
    add("unbounded, g=-0.999", q);
  }
  {
    auto q = Base(0.999, BaseTheta(-1));
    add("peak at tmin, g=0.999", q);
  }
  {
    auto q = Base(0.999, BaseTheta(-1) + 1e-6);
    add("peak 1e-6 rad inside", q);
  }
  {
    auto q = Base(0.999, BaseTheta(-1) - 1e-6);
    add("peak 1e-6 rad outside", q);
  }
  {
    auto q = Base(0.999, BaseTheta(3));
    add("peak at tmax, g=0.999", q);
  }
  {
    auto q = Base(0.999);
    q.lobe.axis = {0, 0, 1};
    add("axis normal to plane (r=0)", q);
  }
  {
    auto q = Base(0.999);
    q.lobe.axis = {std::sin(0.3) * std::sqrt(1 - 1e-8), -std::cos(0.3) * std::sqrt(1 - 1e-8), 1e-4};
    add("axis 1e-4 off the plane", q);
  }
  {
    auto q = Base(0.9);
    V3 off{1e4, 1e4, 1e4};
    q.origin = q.origin + off;
    q.point = q.point + off;
    add("coordinates offset 1e4", q);
  }
  {
    auto q = Base(0.999);
    V3 off{1e4, 1e4, 1e4};
    q.origin = q.origin + off;
    q.point = q.point + off;
    add("offset 1e4, g=0.999", q);
  }
  {
    auto q = Base(0.9);
    q.point = {0, 1e7, 0};
    q.lobe.axis = {0, -1, 0};
    q.tmin = 0;
    q.tmax = 1;
    add("angle width 1e-7 (far point)", q);
  }
  {
    auto q = Base(0.999);
    q.tmin = 0.5;
    q.tmax = 0.5 + 1e-7;
    add("angle width 8e-8 (short)", q);
  }
  {
    auto q = Base(0.9);
    q.lobe = {vrlis::LobeKind::ClampedCosine, {0.6, -0.8, 0}, 0};
    add("surface (clamped cosine)", q);
  }
  {
    auto q = Base(0.999);
    q.lobe = {vrlis::LobeKind::None, {}, 0};
    add("point light, g=0.999", q);
  }
  return cs;
}

template <typename Real, typename From>
vrlis::SegmentQuery<Real> Cast(const vrlis::SegmentQuery<From>& q) {
  vrlis::SegmentQuery<Real> r;
  auto v = [](vrlis::Vec3<From> a) { return vrlis::Vec3<Real>{Real(a.x), Real(a.y), Real(a.z)}; };
  r.origin = v(q.origin);
  r.dir = v(q.dir);
  r.tmin = Real(q.tmin);
  r.tmax = Real(q.tmax);
  r.g = Real(q.g);
  r.point = v(q.point);
  r.lobe = {q.lobe.kind, v(q.lobe.axis), Real(q.lobe.g)};
  r.sigma_t = Real(q.sigma_t);
  return r;
}

template <typename Real, typename From>
vrlis::VrlPointQuery<Real> Cast(const vrlis::VrlPointQuery<From>& q) {
  auto v = [](vrlis::Vec3<From> a) { return vrlis::Vec3<Real>{Real(a.x), Real(a.y), Real(a.z)}; };
  return {v(q.origin), v(q.dir), Real(q.tmin), Real(q.tmax), v(q.line_origin), v(q.line_dir)};
}

// The double version of a query after rounding to float (the float run's exact input).
inline vrlis::SegmentQuery<double> Rounded(const vrlis::SegmentQuery<double>& q) { return Cast<double>(Cast<float>(q)); }
inline vrlis::VrlPointQuery<double> Rounded(const vrlis::VrlPointQuery<double>& q) {
  return Cast<double>(Cast<float>(q));
}

struct HardVrlCase {
  std::string name;
  vrlis::VrlPointQuery<double> q;
  bool integrable = true;
};

inline std::vector<HardVrlCase> HardVrlCases() {
  std::vector<HardVrlCase> cs;
  // VRL along +x from the origin, v in [0, 4]; the camera line along the given direction
  // through the given point.
  auto make = [](V3 line_origin, V3 line_dir, double tmin = 0, double tmax = 4, V3 off = {}) {
    vrlis::VrlPointQuery<double> q;
    q.origin = off;
    q.dir = {1, 0, 0};
    q.tmin = tmin;
    q.tmax = tmax;
    q.line_origin = line_origin + off;
    q.line_dir = Unit(line_dir);
    return q;
  };
  cs.push_back({"skew (generic)", make({1, 0.5, 1}, {0, 0.6, 0.8})});
  cs.push_back({"parallel", make({0, 1, 0}, {1, 0, 0})});
  cs.push_back({"anti-parallel", make({0, 1, 0}, {-1, 0, 0})});
  cs.push_back({"nearly parallel (1e-7)", make({0, 1, 0}, {1, 1e-7, 0})});
  cs.push_back({"intersecting", make({1, 0, 0}, {0, 0.6, 0.8}), false});
  cs.push_back({"h = 1e-9", make({1, 0, 1e-9}, {0, 1, 0})});
  cs.push_back({"intersect at end", make({0, 0, 0}, {0, 1, 0}), false});
  cs.push_back({"closest point outside", make({-3, 0, 1e-3}, {0, 1, 0})});
  cs.push_back({"length 0", make({1, 0.5, 1}, {0, 0.6, 0.8}, 1, 1)});
  cs.push_back({"length 1e-6", make({1, 0.5, 1}, {0, 0.6, 0.8}, 1, 1 + 1e-6)});
  cs.push_back({"length 1e6", make({1, 0.5, 1}, {0, 0.6, 0.8}, 0, 1e6)});
  cs.push_back({"offset 1e4", make({1, 0.5, 1}, {0, 0.6, 0.8}, 0, 4, {1e4, 1e4, 1e4})});
  return cs;
}

}  // namespace vrlis::stability
