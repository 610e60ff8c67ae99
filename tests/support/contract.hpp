#pragma once
// The samplers' contract (angle/segment_sampler.hpp, samplers/vrl_point.hpp) as checks that
// return a description of the first violation, or an empty string. Shared by the Catch2
// suite and the fuzz target (standard library only).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>

#include "segment_integrand.hpp"

namespace vrlis::stability {

// The stated round-trip rule. A camera-segment sampler works in the angle offset delta in
// [0, width] and returns t rounded to Real, so sample(u) can lie a few units in the last
// place of t, or of the angle offset, from the exact inverse of the CDF (the fuzz corpus and
// findings need up to 4 ulps; the rule allows kRoundTripUlps). The round trip holds when u
// lies within 256 eps of the values the CDF takes within that reach:
//   - invert() over [t - dt, t + dt] clipped to [tmin, tmax], dt = kRoundTripUlps ulp(max(|t|, |tmin|))
//     (t is computed as tmin plus an offset, so its error is an ulp of the larger of the two);
//   - for a camera-segment sampler also the distribution's CDF over offset_at(t) +- kRoundTripUlps
//     ulp(width) clipped to [0, width] (near a pole of the angle map a few ulps of the angle
//     reach t = infinity, which no interval in t can express).
// Why the CDF over the reach and not pdf(t) times it: the density in t can change by orders of
// magnitude within one ulp of t (a Cauchy peak narrower than an ulp of t at |t| ~ 1e6 in float;
// the kink of a piecewise-linear fit from its floored nodes to a rising one where the point
// is 1e-12 off the segment's line, so the whole angle range spans a few thousand ulps of t).
// There pdf(t) at the rounded t says nothing of the mass within its ulp, while the CDF does.
// A sample further than that reach from the exact inverse still fails wherever the CDF rises.
// Exempt: samples clamped to the largest finite Real on an unbounded segment (the mass
// beyond it is not representable; pdf() underflows to 0 there).
constexpr int kRoundTripUlps = 16;

template <typename Real>
Real Ulp(Real x) {
  x = std::abs(x);
  Real up = std::nextafter(x, std::numeric_limits<Real>::infinity()) - x;
  return std::isfinite(up) ? up : x - std::nextafter(x, Real(0));
}

// The values of the CDF within the round trip's reach of a sample (empty: every u fails).
struct RoundTripBand {
  double lo = kInf, hi = -kInf;
  void Add(double cdf) {
    lo = std::min(lo, cdf);
    hi = std::max(hi, cdf);
  }
  // Whole: no pointwise round trip to check.
  static RoundTripBand Whole() { return {-kInf, kInf}; }
};

// invert() within kRoundTripUlps ulp(max(|t|, |tmin|)) of t (any sampler with invert()).
template <typename Sampler, typename Real = typename Sampler::Real>
RoundTripBand RoundTripBandInT(const Sampler& s, Real t, Real tmin, Real tmax) {
  double dt = kRoundTripUlps * double(Ulp(std::max(std::abs(t), std::abs(tmin))));
  RoundTripBand band;
  band.Add(double(s.invert(t)));
  band.Add(double(s.invert(Real(std::max(double(t) - dt, double(tmin))))));
  band.Add(double(s.invert(Real(std::min(double(t) + dt, double(tmax))))));
  return band;
}

// A camera-segment sampler's band: the one in t and the CDF within kRoundTripUlps ulp(width)
// of the angle offset of t.
template <typename Sampler, typename Real = typename Sampler::Real>
RoundTripBand RoundTripBandOfSegment(const Sampler& s, Real t, Real tmin, Real tmax) {
  RoundTripBand band = RoundTripBandInT(s, t, tmin, tmax);
  double width = double(s.domain().width()), offset = double(s.domain().offset_at(t));
  double da = kRoundTripUlps * double(Ulp(s.domain().width()));
  for (double at : {std::max(offset - da, 0.0), std::min(offset + da, width)})
    band.Add(std::clamp(double(s.distribution().cdf(Real(at))), 0.0, 1.0));
  return band;
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
// empty), and the round trip: u within 256 eps of band(t) (a RoundTripBand).
template <typename Sampler, typename Real = typename Sampler::Real, typename Extra, typename Band>
std::string CheckSamples(const Sampler& s, Real tmin, Real tmax, const double* us, int n, Extra extra, Band band_at,
                         Violation& v) {
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
    RoundTripBand band = band_at(t);
    const double slack = 256 * double(std::numeric_limits<Real>::epsilon());
    if (!(double(u) >= band.lo - slack && double(u) <= band.hi + slack))
      return (v << "round trip: invert(sample(" << u << ")) = " << c << ", u outside [" << band.lo << ", " << band.hi
                << "] +- 256 eps, the CDF within " << kRoundTripUlps << " ulps of t = " << t << " (pdf " << p << ")")
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
  auto band = [&](Real t) {
    if (!check_round_trip || t == std::numeric_limits<Real>::max() || s.domain().on_line()) return RoundTripBand::Whole();
    return RoundTripBandOfSegment(s, t, q.tmin, q.tmax);
  };
  return CheckSamples(s, q.tmin, q.tmax, us, n, positive, band, v);
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
  auto band = [&](Real t) {
    return check_round_trip ? RoundTripBandInT(s, t, q.tmin, q.tmax) : RoundTripBand::Whole();
  };
  return CheckSamples(s, q.tmin, q.tmax, us, n, positive, band, v);
}

}  // namespace vrlis::stability
