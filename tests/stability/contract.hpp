#pragma once
// The samplers' contract (angle/segment_sampler.hpp, samplers/vrl_point.hpp) as checks that
// return a description of the first violation, or an empty string. Shared by the Catch2
// suite and the fuzz target (standard library only).
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>

#include "integrand.hpp"

namespace vrlis_stab {

// The stated round-trip tolerance. A sampler works in the angle offset delta in [0, width]
// and returns t rounded to Real, so invert(sample(u)) can differ from u by the CDF's change
// over a few units in the last place of t or of the angle, plus a few hundred epsilons:
//   |invert(sample(u)) - u| <= 256 eps + 64 pdf(t) (ulp(max(|t|, |tmin|)) + ulp(width) / (dtheta/dt)).
// (t is computed as tmin plus an offset, so its error is an ulp of the larger of the two.)
// Exempt: samples clamped to the largest finite Real on an unbounded segment (the mass
// beyond it is not representable; pdf() underflows to 0 there).
// dtheta_dt = h / (h^2 + (t - u0)^2) with the sampler's h (0: the angle term is dropped).
template <typename Real>
double RoundTripTolerance(Real t, Real pdf, double width = 0, double dtheta_dt = 0, Real tmin = 0) {
  const Real eps = std::numeric_limits<Real>::epsilon(), inf = std::numeric_limits<Real>::infinity();
  auto ulp = [&](Real x) {
    x = std::abs(x);
    Real up = std::nextafter(x, inf) - x;
    return std::isfinite(up) ? up : x - std::nextafter(x, Real(0));
  };
  double angle = dtheta_dt > 0 ? double(ulp(Real(width))) / dtheta_dt : 0;
  return 256 * double(eps) + 64 * double(pdf) * (double(ulp(std::max(std::abs(t), std::abs(tmin)))) + angle);
}

struct Violation {
  std::ostringstream os;
  bool any = false;
  template <typename T>
  Violation& operator<<(const T& x) {
    any = true;
    os << x;
    return *this;
  }
  std::string str() const { return os.str(); }
};

// A query without a density: invalid (sample NaN, pdf 0, invert NaN) or numerically a point
// (sample tmin, pdf 0, invert 0). `what` names the case in the description.
template <typename Sampler, typename Real = typename Sampler::Real, std::size_t N>
std::string CheckNoDensity(const Sampler& s, bool invalid, Real tmin, const double* us, int n, const Real (&probes)[N],
                           const char* what, Violation& v) {
  for (int i = 0; i < n; ++i) {
    Real u = Real(us[i]), t = s.sample(u);
    if (invalid ? !std::isnan(t) : !(t == tmin))
      return (v << what << ": sample(" << u << ") = " << t << ", not " << (invalid ? "NaN" : "tmin")).str();
  }
  for (Real t : probes) {
    if (s.pdf(t) != 0) return (v << what << ": pdf(" << t << ") = " << s.pdf(t) << ", not 0").str();
    Real c = s.invert(t);
    if (invalid ? !std::isnan(c) : !(c == 0))
      return (v << what << ": invert(" << t << ") = " << c << ", not " << (invalid ? "NaN" : "0")).str();
  }
  return {};
}

// Every sample at the u values: inside [tmin, tmax], a finite pdf >= 0 there, invert in
// [0, 1], the sampler's own check extra(u, t, pdf) (a description of the violation, or
// empty), and |invert(sample(u)) - u| <= tolerance(t, pdf) (infinity: no pointwise round trip).
template <typename Sampler, typename Real = typename Sampler::Real, typename Extra, typename Tolerance>
std::string CheckSamples(const Sampler& s, Real tmin, Real tmax, const double* us, int n, Extra extra,
                         Tolerance tolerance, Violation& v) {
  for (int i = 0; i < n; ++i) {
    Real u = Real(us[i]);
    Real t = s.sample(u);
    if (!std::isfinite(t) || t < tmin || t > tmax)
      return (v << "sample(" << u << ") = " << t << " outside [" << tmin << ", " << tmax << "]").str();
    Real p = s.pdf(t);
    if (!std::isfinite(p) || p < 0) return (v << "pdf(sample(" << u << ") = " << t << ") = " << p).str();
    std::string own = extra(u, t, p);
    if (!own.empty()) return own;
    Real c = s.invert(t);
    if (!(c >= 0 && c <= 1)) return (v << "invert(" << t << ") = " << c).str();
    double tol = tolerance(t, p);
    if (!(std::abs(double(c) - double(u)) <= tol))
      return (v << "round trip: invert(sample(" << u << ")) = " << c << ", error " << std::abs(double(c) - double(u))
                << " > tolerance " << tol << " (t = " << t << ", pdf " << p << ")")
          .str();
  }
  return {};
}

// Checks one sampler on one query at the given u values. check_round_trip: the pointwise
// round trip (not for CauchyMixture, whose sample() picks a component first).
template <typename Sampler>
std::string CheckSegmentSampler(const Sampler& s, const vrlis::SegmentQuery<typename Sampler::Real>& q,
                                const double* us, int n, bool check_round_trip) {
  using Real = typename Sampler::Real;
  Violation v;
  v.os.precision(9);
  vrlis::QueryError err = vrlis::Validate(q);
  if (s.valid() != (err == vrlis::QueryError::None) || s.error() != err)
    return (v << "valid()/error() disagree with Validate: " << vrlis::Describe(err)).str();
  const Real probes[] = {q.tmin, q.tmax, Real(0), Real(1), std::numeric_limits<Real>::infinity(),
                         -std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::quiet_NaN()};
  if (!s.valid()) return CheckNoDensity(s, true, q.tmin, us, n, probes, "invalid query", v);
  // Degenerate (contract): shorter than min<Real> / epsilon<Real> (zero length included), or
  // an angle width that underflows.
  bool degenerate = !(s.domain().width() >= std::numeric_limits<Real>::min()) ||
                    !((q.tmax - q.tmin) * std::numeric_limits<Real>::epsilon() >= std::numeric_limits<Real>::min());
  if (q.tmax == q.tmin && !degenerate) return (v << "zero-length segment with a non-zero angle width").str();
  if (degenerate) return CheckNoDensity(s, false, q.tmin, us, n, probes, "degenerate segment", v);
  RefQuery ref(q);
  ref.clamp_margin = 1e-6;
  for (Real t : probes) {
    Real p = s.pdf(t), c = s.invert(t);
    if (!std::isfinite(p) || p < 0) return (v << "pdf(" << t << ") = " << p).str();
    if (!std::isnan(t) && !(c >= 0 && c <= 1)) return (v << "invert(" << t << ") = " << c).str();
  }
  // Positive where the integrand is, unless the density is below what Real can hold: the
  // check applies where equiangular sampling's density exceeds 1e12 times the smallest
  // normal Real (the samplers' densities are within that factor of it).
  auto positive = [&](Real u, Real t, Real p) {
    double f = ref.f(double(t));
    bool representable = ref.EquiangularDensity(double(t)) > 1e12L * std::numeric_limits<Real>::min();
    if (f > 0 && std::isfinite(f) && representable && !(p > 0))
      return (v << "pdf(" << t << ") = 0 where the integrand is " << f << " (u = " << u << ")").str();
    return std::string();
  };
  // (Not on the line: there the density is a spike as wide as the rounding of h.)
  auto tolerance = [&](Real t, Real p) {
    if (!check_round_trip || t == std::numeric_limits<Real>::max() || s.domain().on_line()) return kInf;
    return RoundTripTolerance(t, p, double(s.domain().width()), double(s.domain().dtheta_dt(t)), q.tmin);
  };
  return CheckSamples(s, q.tmin, q.tmax, us, n, positive, tolerance, v);
}

// VrlPoint's contract.
// Coordinates up to sqrt(max<Real>) / 8 are accepted (QueryError::OutOfRange beyond).
template <typename Real>
bool InRange(vrlis::Vec3<Real> v) {
  Real m = vrlis::MaxCoordinate<Real>();
  return std::abs(v.x) <= m && std::abs(v.y) <= m && std::abs(v.z) <= m;
}

template <typename Real>
bool VrlQueryValid(const vrlis::VrlPointQuery<Real>& q) {
  auto unit = [](vrlis::Vec3<Real> d) { return std::abs(vrlis::Dot(d, d) - 1) <= Real(2e-3); };
  return vrlis::IsFinite(q.origin) && vrlis::IsFinite(q.dir) && vrlis::IsFinite(q.line_origin) &&
         vrlis::IsFinite(q.line_dir) && std::isfinite(q.tmin) && std::isfinite(q.tmax) && q.tmax >= q.tmin &&
         unit(q.dir) && unit(q.line_dir) && InRange(q.origin) && InRange(q.line_origin) &&
         std::abs(q.tmin) <= vrlis::MaxCoordinate<Real>() && std::abs(q.tmax) <= vrlis::MaxCoordinate<Real>();
}

template <typename Real>
std::string CheckVrlPoint(const vrlis::VrlPoint<Real>& s, const vrlis::VrlPointQuery<Real>& q, const double* us, int n,
                          bool check_round_trip = true) {
  Violation v;
  v.os.precision(9);
  bool valid = VrlQueryValid(q);
  if (s.valid() != valid) return (v << "valid() = " << s.valid() << ", expected " << valid).str();
  if (s.error() != vrlis::Validate(q) || valid != (s.error() == vrlis::QueryError::None))
    return (v << "error() = " << vrlis::Describe(s.error()) << ", Validate: " << vrlis::Describe(vrlis::Validate(q))).str();
  const Real probes[] = {q.tmin, q.tmax, Real(0), std::numeric_limits<Real>::infinity(),
                         -std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::quiet_NaN()};
  if (!valid) return CheckNoDensity(s, true, q.tmin, us, n, probes, "invalid query", v);
  // Shorter than min<Real> / epsilon<Real>: numerically a point.
  if (!((q.tmax - q.tmin) * std::numeric_limits<Real>::epsilon() >= std::numeric_limits<Real>::min()))
    return CheckNoDensity(s, false, q.tmin, us, n, probes, "zero-length VRL", v);
  for (Real t : probes) {
    Real p = s.pdf(t);
    if (!std::isfinite(p) || p < 0) return (v << "pdf(" << t << ") = " << p).str();
  }
  auto positive = [&](Real u, Real t, Real p) {
    return p > 0 ? std::string() : (v << "pdf(sample(" << u << ") = " << t << ") = " << p).str();
  };
  auto tolerance = [&](Real t, Real p) { return check_round_trip ? RoundTripTolerance(t, p, 0, 0, q.tmin) : kInf; };
  return CheckSamples(s, q.tmin, q.tmax, us, n, positive, tolerance, v);
}

}  // namespace vrlis_stab
