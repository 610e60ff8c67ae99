#pragma once
// The per-configuration checks shared by the segment-sampler and VRL-point tests.
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "integrand.hpp"
#include "sampler_types.hpp"
#include "stats.hpp"

namespace vrlis::test {

template <typename Real>
const char* RealName() { return std::is_same_v<Real, float> ? "float" : "double"; }

template <typename S>
std::string Label() { return SamplerName<S>() + "/" + RealName<typename S::Real>(); }

// Tolerances per Real type. Each is a bound on rounding, with headroom; the summary file
// records the worst value actually seen so that they can be tightened.
template <typename Real>
struct Tolerance;
template <>
struct Tolerance<double> {
  static constexpr double normalisation = 1e-8;  // |integral of pdf - 1|
  static constexpr double round_trip = 1e-12;    // |invert(sample(u)) - u| floor, beside the rounding budget
  static constexpr double derivative = 1e-6;     // relative, on top of the rounding term
  static constexpr double fd_step = 1e-5;        // finite-difference step / local length scale
  static constexpr double estimator_bias = 1e-9; // relative bias of f / pdf allowed for rounding
  static constexpr double quadrature = 1e-11;    // relative tolerance for quadrature of the pdf
};
template <>
struct Tolerance<float> {
  // A Cauchy of scale ~2e-4 rad just beyond the far end of a long segment (g = -0.99): its
  // offsets, of size pi, carry float rounding of ~2e-7 against a peak distance of ~1e-3, which
  // moves the density's mass by ~1e-4 of its weight (the Cauchy sum's 8e-5, the equal-weight
  // mixture's 2e-4).
  static constexpr double normalisation = 3e-4;
  static constexpr double round_trip = 1e-5;
  static constexpr double derivative = 2e-3;
  static constexpr double fd_step = 3e-3;
  static constexpr double estimator_bias = 1e-4;
  // 30x below the normalisation tolerance: a float pdf is noisy at 1e-7, and asking for
  // more refines on rounding (the float battery took 1.5x the time at 1e-6).
  static constexpr double quadrature = 1e-5;
};

inline constexpr long kSamples = 20000;
inline constexpr double kBinProbability = 1.0 / 50;  // ~50 bins, 400 expected counts each

// Uniform numbers in [0, 1] for the sampler, from a fixed seed (no stratification).
template <typename Real>
std::vector<Real> UniformNumbers(std::uint64_t seed, long n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0, 1);
  std::vector<Real> u(std::size_t(n), Real(0));
  for (auto& x : u) x = Real(uni(rng));
  return u;
}

// A chi-square test of samples (given in the coordinate x) against a density in x, bins
// from quadrature of the density over a refined grid. `t_of_x` maps x to the sampler's own
// variable, so that no bin is narrower than 64 ulps of Real there: Real cannot place a
// sample more finely than that, and its pdf means nothing at smaller scales.
template <typename Real, typename Density, typename TOfX>
ChiSquare BinnedChiSquare(Density density_x, TOfX t_of_x, double a, double b, const std::vector<double>& features,
                          const std::vector<double>& x_samples) {
  std::vector<double> edges = RefinedGrid(a, b, features);
  std::vector<double> cell_p = CellIntegrals(density_x, edges, std::max(1e-9, Tolerance<Real>::quadrature));
  auto wide_enough = [&](double lo, double hi) {
    double tl = t_of_x(lo), th = t_of_x(hi);
    if (!std::isfinite(th) || !std::isfinite(tl)) return true;
    return th - tl >= 64 * double(std::numeric_limits<Real>::epsilon()) * std::max(std::abs(tl), std::abs(th));
  };
  std::vector<double> bin_edges, bin_p;
  MergeCells(edges, cell_p, kBinProbability, wide_enough, bin_edges, bin_p);
  return PearsonTest(Histogram(x_samples, bin_edges), bin_p, long(x_samples.size()));
}

// A chi-square test that values in [0, 1] are uniform, on 20 equal bins.
inline ChiSquare UniformityChiSquare(const std::vector<double>& v) {
  std::vector<double> edges(21), p(20, 1.0 / 20);
  for (int i = 0; i <= 20; ++i) edges[std::size_t(i)] = i / 20.0;
  return PearsonTest(Histogram(v, edges), p, long(v.size()));
}

struct DerivativeCheck {
  int checked = 0, skipped = 0, failed = 0;
  double worst_relative = 0;   // |finite difference - pdf| / pdf
  double worst_over_tol = 0;   // the same error over the allowed error (<= 1 passes)
  std::string worst_note;
};

// pdf(t) against the derivative of invert at the points ts. The central difference of the
// CDF over [lo, hi] is exactly the mean of the pdf there, which Simpson's rule gives to
// O(step^4); where Simpson and the trapezoid disagree the pdf is too curved (or kinked, as
// Novak's is at its nodes) at this step, so the step is shrunk, and the point skipped (and
// counted) if even the smallest step does not resolve it. A point where Simpson disagrees
// is checked again against the adaptive Gauss-Kronrod integral of the pdf, which resolves
// kinks and narrow spikes. Allowed error: relative tolerance plus the CDF's rounding (a few
// ulps) over the step.
//
// The rounding term: invert(t) computes with t and with the query's coordinates, so it is
// F(t + e) for an e of a few ulps of the magnitudes involved (`magnitude`), plus a few ulps
// of u; over a step of width w that is (eps + pdf eps magnitude) / w.
template <typename S>
DerivativeCheck CheckDerivative(const S& s, double u0, double scale_h, double tmin, double tmax,
                                const std::vector<double>& ts, double magnitude) {
  using Real = typename S::Real;
  const double eps = std::numeric_limits<Real>::epsilon();
  const double rel_tol = Tolerance<Real>::derivative;
  DerivativeCheck r;
  for (double t : ts) {
    bool done = false;
    for (double shrink : {1.0, 0.25, 0.0625, 0.015625}) {
      double hs = Tolerance<Real>::fd_step * shrink * (scale_h + std::abs(t - u0));
      Real lo = Real(t - hs), hi = Real(t + hs);
      if (!(double(lo) >= tmin && double(hi) <= tmax && hi > lo)) continue;
      Real mid = Real((double(lo) + double(hi)) / 2);
      double plo = s.pdf(lo), pmid = s.pdf(mid), phi = s.pdf(hi);
      double simpson = (plo + 4 * pmid + phi) / 6, trapezoid = (plo + phi) / 2;
      // Simpson's error is about (S - T)^2 / S for the smooth bumps met here (Cauchy-like).
      if (!(Square((simpson - trapezoid) / simpson) <= 0.1 * rel_tol)) continue;
      double width = double(hi) - double(lo);
      double fd = (double(s.invert(hi)) - double(s.invert(lo))) / width;
      double err = std::abs(fd - simpson);
      // ... and the angle offset's rounding (an ulp of ~pi, times the angular density).
      double dt_dtheta = (scale_h * scale_h + (t - u0) * (t - u0)) / scale_h;
      double allowed = rel_tol * simpson + 32 * eps * (1 + simpson * (magnitude + std::abs(t) + 4 * dt_dtheta)) / width;
      ++r.checked;
      // Simpson cannot see a spike narrower than the step, nor a kink between probes: only
      // a disagreement that the adaptive integral of the pdf confirms is a failure.
      if (!(err <= allowed)) {
        double quad_error = 0;
        double mean = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
                          [&](double x) { return double(s.pdf(Real(x))); }, double(lo), double(hi), 12, 0.1 * rel_tol,
                          &quad_error) / width;
        err = std::abs(fd - mean);
        if (!(err <= allowed)) ++r.failed;
      }
      if (err / simpson > r.worst_relative) r.worst_relative = err / simpson;
      if (!(err / allowed <= r.worst_over_tol)) {
        r.worst_over_tol = err / allowed;
        r.worst_note = "t=" + std::to_string(t) + " pdf=" + std::to_string(simpson) + " fd=" + std::to_string(fd);
      }
      done = true;
      break;
    }
    if (!done) ++r.skipped;
  }
  return r;
}

}  // namespace vrlis::test

namespace vrlis::test {

// The smallest and largest of f at 17 points of x -+ dx (clamped to [lo, hi]): the values
// f takes within the rounding dx of its argument, a spike inside included.
template <typename F>
std::pair<double, double> RangeAround(F f, double x, double dx, double lo, double hi) {
  std::pair<double, double> r{kInf, 0};
  for (int i = -8; i <= 8; ++i) {
    double v = f(std::clamp(x + dx * i / 8, lo, hi));
    r = {std::min(r.first, v), std::max(r.second, v)};
  }
  return r;
}

// Whether a density computed alongside a sample (sample_pdf) equals the density evaluated
// at the sample up to rounding: within [lo, hi], the range the evaluation takes over the
// rounding of its arguments, widened by 64 ulps, or both below what Real represents.
template <typename Real>
bool FusedPdfAgrees(Real fused, std::pair<double, double> range) {
  const double eps = std::numeric_limits<Real>::epsilon(), tiny = 1e6 * double(std::numeric_limits<Real>::min());
  return double(fused) >= range.first * (1 - 64 * eps) - tiny && double(fused) <= range.second * (1 + 64 * eps) + tiny;
}

}  // namespace vrlis::test
