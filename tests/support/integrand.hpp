#pragma once
// Reference geometry and integrands for the lib tests, in double, written from 3D vectors.
//
// Nothing here calls the library's phase functions or its angle-domain reduction: those
// are what the tests check, so the reference must not share their code (or their bugs).
#include <vrlis/vrlis.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace vrlis::test {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

struct V3 {
  double x = 0, y = 0, z = 0;
};
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator-(V3 a) { return {-a.x, -a.y, -a.z}; }
inline V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double Dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 Cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double Norm(V3 a) { return std::sqrt(Dot(a, a)); }
inline V3 Unit(V3 a) { return (1 / Norm(a)) * a; }
inline double Square(double x) { return x * x; }

// Henyey-Greenstein for the angle between the unit vectors a and b. 1 - cos = |a - b|^2 / 2
// and 1 + cos = |a + b|^2 / 2 keep the denominator's digits near the peak as |g| -> 1.
inline double HgBetween(double g, V3 a, V3 b) {
  double denom = g >= 0 ? Square(1 - g) + g * Dot(a - b, a - b) : Square(1 + g) - g * Dot(a + b, a + b);
  return (1 - g) * (1 + g) / (4 * kPi * denom * std::sqrt(denom));
}

// A camera-segment query in double, the form the references work with.
struct Config {
  std::string name;
  V3 origin, dir;
  double tmin = 0, tmax = 1;
  double g = 0;
  V3 point;
  vrlis::LobeKind kind = vrlis::LobeKind::None;
  V3 axis{0, 0, 1};
  double lobe_g = 0;
};

template <typename Real>
vrlis::Vec3<Real> ToVec(V3 a) { return {Real(a.x), Real(a.y), Real(a.z)}; }
template <typename Real>
V3 FromVec(vrlis::Vec3<Real> a) { return {double(a.x), double(a.y), double(a.z)}; }

template <typename Real>
vrlis::SegmentQuery<Real> ToQuery(const Config& c) {
  vrlis::SegmentQuery<Real> q;
  q.origin = ToVec<Real>(c.origin);
  q.dir = ToVec<Real>(c.dir);
  q.tmin = Real(c.tmin);
  q.tmax = Real(c.tmax);
  q.g = Real(c.g);
  q.point = ToVec<Real>(c.point);
  q.lobe = {c.kind, ToVec<Real>(c.axis), Real(c.lobe_g)};
  return q;
}

// The configuration with every number rounded to Real: the reference then describes the
// query the sampler actually received, not the one we meant to give it.
template <typename Real>
Config AsSeenBy(const Config& c) {
  vrlis::SegmentQuery<Real> q = ToQuery<Real>(c);
  Config r = c;
  r.origin = FromVec(q.origin);
  r.dir = FromVec(q.dir);
  r.tmin = double(q.tmin);
  r.tmax = double(q.tmax);
  r.g = double(q.g);
  r.point = FromVec(q.point);
  r.axis = FromVec(q.lobe.axis);
  r.lobe_g = double(q.lobe.g);
  return r;
}

// The true integrand at t: the segment lobe HG(g, dir . w) times the point lobe at p
// (evaluated for the direction -w from p to x(t)) over |p - x(t)|^2, w = unit(p - x(t)).
inline double TrueIntegrand(const Config& c, double t) {
  V3 x = c.origin + t * c.dir;
  V3 w = c.point - x;
  double d2 = Dot(w, w);
  if (!(d2 > 0) || !std::isfinite(d2)) return 0;
  V3 wn = (1 / std::sqrt(d2)) * w;
  double segment = HgBetween(c.g, Unit(c.dir), wn);
  double point = 1;
  switch (c.kind) {
    case vrlis::LobeKind::HenyeyGreenstein: point = HgBetween(c.lobe_g, Unit(c.axis), -wn); break;
    case vrlis::LobeKind::ClampedCosine: point = std::max(0.0, Dot(Unit(c.axis), -wn)) / kPi; break;
    case vrlis::LobeKind::None: break;
  }
  return segment * point / d2;
}

// The change of variables t = u0 + h tan(theta) used for every quadrature over a segment:
// it flattens the inverse-square falloff and maps an unbounded segment to a finite
// interval. Any monotone map would do; this one keeps peaked integrands well resolved.
struct AngleMap {
  double u0 = 0, h = 1, theta_a = 0, theta_b = 0;
  double t(double theta) const { return u0 + h * std::tan(theta); }
  double theta(double t) const { return std::atan((t - u0) / h); }
  double dt_dtheta(double theta) const { return h / Square(std::cos(theta)); }
};

inline AngleMap MapFor(const Config& c) {
  AngleMap m;
  V3 d = c.point - c.origin;
  m.u0 = Dot(d, c.dir) / Dot(c.dir, c.dir);
  m.h = std::max(Norm(d - m.u0 * c.dir), 1e-300);
  m.theta_a = m.theta(c.tmin);
  m.theta_b = std::isfinite(c.tmax) ? m.theta(c.tmax) : kPi / 2;
  return m;
}

// Angles where the integrand (or a sampler fitted to it) may peak, kink or vanish: the
// point lobe's axis seen in the angle domain, theta_e, and its quarter-turn images.
// x(theta) - p is proportional to sin(theta) dir - cos(theta) n, so the point lobe's cosine
// is a cos(theta) + b sin(theta) with a = -axis . n, b = axis . dir.
inline std::vector<double> FeatureAngles(const Config& c, const AngleMap& m) {
  std::vector<double> out{0.0};
  if (c.kind != vrlis::LobeKind::None) {
    V3 foot = c.origin + m.u0 * c.dir;
    V3 n = Unit(c.point - foot);
    double a = -Dot(c.axis, n), b = Dot(c.axis, c.dir);
    if (std::hypot(a, b) > 0) {
      double theta_e = std::atan2(b, a);
      for (int k = -4; k <= 4; ++k) out.push_back(theta_e + k * kPi / 2);
    }
  }
  std::vector<double> inside;
  for (double x : out)
    if (x > m.theta_a && x < m.theta_b) inside.push_back(x);
  return inside;
}

// ---- Configurations -------------------------------------------------------------------

inline V3 RandomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  for (;;) {
    V3 v{n(rng), n(rng), n(rng)};
    if (Norm(v) > 1e-6) return Unit(v);
  }
}

inline V3 RandomPerpendicular(std::mt19937_64& rng, V3 dir) {
  for (;;) {
    V3 v = RandomUnit(rng);
    V3 p = v - Dot(v, dir) * dir;
    if (Norm(p) > 1e-3) return Unit(p);
  }
}

inline double LogUniform(std::mt19937_64& rng, double lo, double hi) {
  return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
}

inline constexpr double kAsymmetries[] = {-0.99, -0.9, -0.5, 0.0, 0.5, 0.9, 0.99};
inline constexpr int kRandomConfigsPerG = 20;

// Camera-like segments of length 0.1..10, points 0.05..5 from the line with the foot of the
// perpendicular inside or outside, random lobe axes; mostly HG point lobes with the same g,
// a few clamped-cosine and lobe-free points.
inline Config RandomConfig(double g, int index) {
  std::mt19937_64 rng(0x5eed0000u + 1000u * std::uint64_t(std::lround((g + 1) * 100)) + std::uint64_t(index));
  std::uniform_real_distribution<double> uni(0, 1);
  Config c;
  c.name = "random #" + std::to_string(index);
  c.origin = {4 * uni(rng) - 2, 4 * uni(rng) - 2, 4 * uni(rng) - 2};
  c.dir = RandomUnit(rng);
  double length = LogUniform(rng, 0.1, 10);
  c.tmin = uni(rng) < 0.5 ? 0 : 0.5 * uni(rng);
  c.tmax = c.tmin + length;
  c.g = g;
  double along = c.tmin + (2 * uni(rng) - 0.5) * length;
  c.point = c.origin + along * c.dir + LogUniform(rng, 0.05, 5) * RandomPerpendicular(rng, c.dir);
  c.axis = RandomUnit(rng);
  if (index % 10 == 3) {
    c.kind = vrlis::LobeKind::ClampedCosine;
  } else if (index % 10 == 7) {
    c.kind = vrlis::LobeKind::None;
  } else {
    c.kind = vrlis::LobeKind::HenyeyGreenstein;
    c.lobe_g = g;
  }
  return c;
}

// The point lobe's axis that puts its peak on the direction from p to x(t_peak).
inline V3 AxisPeakingAt(const Config& c, double t_peak) {
  V3 to = Unit(c.origin + t_peak * c.dir - c.point);
  return c.lobe_g < 0 ? -to : to;
}

// Hand-made hard cases. The segment runs along a tilted axis so that no coordinate is zero.
inline std::vector<Config> HardConfigs(double g) {
  std::vector<Config> out;
  V3 dir = Unit(V3{1, 0.3, -0.2});
  V3 n = Unit(Cross(dir, V3{0, 0, 1}));
  V3 origin{0.3, -0.7, 1.1};
  auto make = [&](std::string name, double tmin, double tmax, double foot, double h, double t_peak) {
    Config c;
    c.name = std::move(name);
    c.origin = origin;
    c.dir = dir;
    c.tmin = tmin;
    c.tmax = tmax;
    c.g = g;
    c.point = origin + foot * dir + h * n;
    c.kind = vrlis::LobeKind::HenyeyGreenstein;
    c.lobe_g = g;
    c.axis = AxisPeakingAt(c, t_peak);
    return c;
  };
  out.push_back(make("peak inside", 0, 4, 2, 0.5, 1.2));
  out.push_back(make("peak outside", 0, 4, 2, 0.5, -3));
  out.push_back(make("peak at tmin", 0, 4, 2, 0.5, 0));
  out.push_back(make("peak at tmax", 0, 4, 2, 0.5, 4));
  out.push_back(make("tiny h, peak inside", 0, 1, 0.3, 1e-3, 0.302));
  out.push_back(make("tiny h, foot at tmin", 0, 1, 0, 1e-3, 0.5));
  out.push_back(make("long segment", 0, 1000, 3, 0.2, 2.5));
  out.push_back(make("point behind the start", 0, 5, -2, 0.01, 1));
  out.push_back(make("negative tmin", -3, 2, 0.5, 0.7, -1));
  out.push_back(make("unbounded, foot inside", 0, kInf, 2, 0.3, 5));
  out.push_back(make("unbounded, point behind", 0, kInf, -5, 0.4, 1));
  Config axis_out_of_plane = make("axis out of plane", 0, 3, 1, 0.5, 1);
  axis_out_of_plane.axis = Unit(Cross(dir, n));
  out.push_back(axis_out_of_plane);
  Config cosine = make("clamped cosine facing the segment", 0, 4, 2, 0.5, 1);
  cosine.kind = vrlis::LobeKind::ClampedCosine;
  cosine.axis = Unit(-1.0 * n + 0.3 * dir);
  out.push_back(cosine);
  Config none = make("no point lobe, unbounded", 1, kInf, 0, 0.2, 0);
  none.kind = vrlis::LobeKind::None;
  out.push_back(none);
  return out;
}

inline std::vector<Config> ConfigsFor(double g) {
  std::vector<Config> out;
  for (int i = 0; i < kRandomConfigsPerG; ++i) out.push_back(RandomConfig(g, i));
  for (Config& c : HardConfigs(g)) out.push_back(std::move(c));
  return out;
}

}  // namespace vrlis::test
