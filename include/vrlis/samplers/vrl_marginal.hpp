#pragma once
// Step one of the medium-to-medium estimator, following the marginal of the whole integrand.
//
// VrlPoint samples the VRL point y(v) with density p1(v) proportional to the inverse
// distance to the camera *line*; it ignores the camera segment's extent, the transmittance
// (along the VRL, to the camera segment, along the camera ray) and both phase lobes. The
// ideal step one follows the marginal
//   M(v) = Int_0^s f(u, v) du = T(v) Int F(theta) dtheta / h(v),
// where theta is the camera step's angle variable seen from y(v), h(v) the distance from
// y(v) to the camera line (exactly VrlPoint's inverse-distance factor) and F the phase
// product times the transmittances T(u) T(|y - x(u)|) (FullProductTarget, up to the
// factor exp(-sigma_t |y - x(0)|) by which it is normalised).
//
// So M / p1 is bounded and smooth: r(v) = T(v) exp(-sigma_t |y(v) - x(0)|) Int F dtheta.
// We warp by VrlPoint's CDF, xi = P1(v) (which absorbs the singular inverse distance), and
// fit a piecewise-linear density PL(xi) through kNodes uniform nodes whose values are r at
// those nodes, with Int F dtheta estimated by a kRule-point Gauss-Legendre rule over the
// camera step's angle interval, cut into pieces that isolate both lobes' peaks (kSplit: the
// point lobe's peak +- 3 (1 - |g|), and 3 (1 - |g|) plus the pole's distance from the end
// nearest the segment lobe's pole; without the cuts the rule misses |g| -> 1 spikes and the
// mean relative variance at |g| = 0.99 doubles). kClosest adds a node at the VRL point
// closest to the camera line (measured: no gain, so off by default). Then
//   pdf(v) = p1(v) PL(P1(v)) / Int PL,   sample(u) = P1^-1(PL^-1(u)).
// Node values are floored at kRelativeFloor x their largest, so the density is positive
// wherever the integrand is and a poor estimate costs at most a bounded factor in variance.
// The fit costs kNodes x (VrlPoint sample + angle domain + 1 to 5 pieces x kRule target
// evaluations): about 2 us in float, 20 times VrlPoint (docs/bench.md).
//
// Contract (same as VrlPoint): valid() is false for non-finite input, non-unit directions,
// tmax < tmin, a negative camera length, |g| >= 1 or sigma_t < 0; then sample() and invert()
// return NaN and pdf() returns 0. A VRL shorter than 1 / max<Real> samples tmin with pdf 0.
// A zero-length camera segment (the integrand is 0) or a marginal estimate that underflows
// at every node falls back to VrlPoint's density. Parallel and intersecting lines are
// handled by VrlPoint and AngleDomain (finite, positive estimates).
#include <algorithm>
#include <array>
#include <limits>
#include <string_view>

#include "../angle/full_product.hpp"
#include "../core/piecewise_linear.hpp"
#include "vrl_point.hpp"

namespace vrlis {

template <typename Real>
struct VrlMarginalQuery {
  Vec3<Real> origin{}, dir{};  // the VRL y(v) = origin + v dir, dir unit length
  Real tmin = 0, tmax = 0;     // both finite
  Vec3<Real> camera_origin{}, camera_dir{};  // the camera segment x(u) = camera_origin + u camera_dir
  Real camera_length = 0;                     // u in [0, camera_length], finite
  Real g = 0;        // Henyey-Greenstein asymmetry of the medium (both scattering events)
  Real sigma_t = 0;  // homogeneous extinction

  VrlPointQuery<Real> vrl_point_query() const { return {origin, dir, tmin, tmax, camera_origin, camera_dir}; }
};

template <typename R = float, int kNodes = 8, int kRule = 2, bool kSplit = true, bool kClosest = false>
class VrlMarginal {
  static_assert(kNodes >= 2, "a piecewise-linear density needs two nodes");
  static_assert(kRule >= 1 && kRule <= 3, "Gauss-Legendre rules of 1 to 3 points");

 public:
  using Real = R;
  static constexpr int kNodeCount = kNodes;  // uniform nodes; plus the closest point (kClosest)
  static constexpr Real kRelativeFloor = Real(0.02);

  explicit VrlMarginal(const VrlMarginalQuery<Real>& q) : vp_(q.vrl_point_query()) {
    valid_ = vp_.valid() && std::isfinite(q.camera_length) && q.camera_length >= 0 && std::abs(q.g) < 1 &&
             std::isfinite(q.sigma_t) && q.sigma_t >= 0;
    value_.fill(1);
    for (int j = 0; j < kMax; ++j) xi_[j] = Real(j) / Real(kMax - 1);
    if (valid_) PlaceNodes(q);
    if (valid_ && q.camera_length > 0) Fit(q);
    fit_ = PiecewiseLinear<Real, kMax>(xi_, value_, count_);
  }

  // Step one of a medium-to-medium gather (a finite camera segment).
  explicit VrlMarginal(const MediumGatherQuery<Real>& q)
      : VrlMarginal(VrlMarginalQuery<Real>{q.vrl.origin, q.vrl.dir, 0, q.vrl.length, q.camera.at(q.camera.tmin),
                                           q.camera.dir, q.camera.tmax - q.camera.tmin, q.medium.g, q.medium.sigma_t}) {}

  bool valid() const { return valid_; }
  const VrlPoint<Real>& vrl_point() const { return vp_; }

  Real sample(Real u) const { return sample_pdf(u).t; }

  Real pdf(Real v) const {
    if (!valid_) return 0;
    Real p1 = vp_.pdf(v);
    if (!(p1 > 0)) return 0;
    return p1 * fit_.pdf(vp_.invert(v));
  }

  // The density is the product of the two warps' densities at the sampled xi and v.
  SegmentSample<Real> sample_pdf(Real u) const {
    if (!valid_) return {kNaN, 0};
    SegmentSample<Real> xi = fit_.sample_pdf(u);
    SegmentSample<Real> v = vp_.sample_pdf(xi.t);
    return {v.t, v.pdf * xi.pdf};
  }

  Real invert(Real v) const {
    if (!valid_) return kNaN;
    return fit_.cdf(vp_.invert(v));
  }

  // The fitted density over xi = VrlPoint.invert(v) (for studies): value(xi) / total.
  Real xi_density(Real xi) const { return fit_.pdf(xi); }
  static constexpr Real node(int j) { return Real(j) / Real(kNodes - 1); }
  // The fit's nodes in xi (count() of them): the uniform ones and the closest point.
  int count() const { return fit_.count(); }
  Real fitted_node(int j) const { return fit_.node(j); }

 private:
  static constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
  static constexpr int kMax = kNodes + (kClosest ? 1 : 0);

  // Uniform nodes in xi, and the VRL point closest to the camera line where the marginal
  // over VrlPoint's density peaks when the lines nearly meet (|g| -> 1: both lobes).
  void PlaceNodes(const VrlMarginalQuery<Real>& q) {
    count_ = kNodes;
    for (int j = 0; j < kNodes; ++j) xi_[j] = node(j);
    if constexpr (kClosest) {
      Vec3<Real> cr = Cross(q.dir, q.camera_dir), d = q.camera_origin - q.origin;
      Real sin2 = Dot(cr, cr);
      if (!(sin2 > Real(1e-6))) return;
      Real v0 = (Dot(d, q.dir) - Dot(d, q.camera_dir) * Dot(q.dir, q.camera_dir)) / sin2;
      if (!(v0 > q.tmin && v0 < q.tmax)) return;
      Real x0 = vp_.invert(v0);
      int j = std::min(static_cast<int>(x0 * Real(kNodes - 1)), kNodes - 2);
      Real gap = Real(0.05) / Real(kNodes - 1);
      if (!(x0 - xi_[j] > gap && xi_[j + 1] - x0 > gap)) return;
      for (int k = kNodes; k > j + 1; --k) xi_[k] = xi_[k - 1];
      xi_[j + 1] = x0;
      count_ = kNodes + 1;
    }
  }

  void Fit(const VrlMarginalQuery<Real>& q) {
    // Gauss-Legendre on [0, 1].
    constexpr Real x2 = Real(0.21132486540518711775), x3 = Real(0.11270166537925831148);
    const Real xs[3] = {kRule == 1 ? Real(0.5) : kRule == 2 ? x2 : x3, kRule == 2 ? 1 - x2 : Real(0.5), 1 - x3};
    const Real ws[3] = {kRule == 1 ? Real(1) : kRule == 2 ? Real(0.5) : Real(5) / 18,
                        kRule == 2 ? Real(0.5) : Real(8) / 18, Real(5) / 18};
    SegmentQuery<Real> sq = MediumToMediumQuery(q.camera_origin, q.camera_dir, Real(0), q.camera_length, q.origin,
                                                q.dir, q.g, q.sigma_t);
    std::array<Real, kMax> depth;
    for (int j = 0; j < count_; ++j) {
      Real v = vp_.sample(xi_[j]);
      sq.point = q.origin + v * q.dir;
      AngleDomain<Real> dom(sq);
      FullProductTarget<Real> target(sq, dom);
      Real width = dom.width(), peak = target.point_peak();
      auto rule = [&](Real a, Real b) {
        Real sum = 0;
        for (int i = 0; i < kRule; ++i) sum += ws[i] * target(a + xs[i] * (b - a));
        return (b - a) * sum;
      };
      if constexpr (!kSplit) {
        value_[j] = rule(Real(0), width);
      } else {
        // Pieces that isolate the lobes' peaks, so the rule sees them: the point lobe's peak
        // (if inside) with a few lobe widths (1 - |g|) on either side, and the segment lobe's
        // peak, a pole at or beyond one end, with a few lobe widths plus its distance.
        std::array<Real, 6> cut;
        int n = 0;
        cut[n++] = 0;
        Real lobe = 3 * (1 - std::abs(q.g));
        if (!target.point_lobe_flat() && peak > 0 && peak < width) {
          if (peak - lobe > 0) cut[n++] = peak - lobe;
          cut[n++] = peak;
          if (peak + lobe < width) cut[n++] = peak + lobe;
        }
        if (q.g != 0) {
          Real pole = kPi<Real> / 2 + (q.g > 0 ? dom.theta_a() : -dom.theta_b());  // beyond its end
          Real reach = lobe + pole;
          if (reach < width / 2) cut[n++] = q.g > 0 ? reach : width - reach;
        }
        cut[n++] = width;
        std::sort(cut.begin(), cut.begin() + n);
        Real sum = 0;
        for (int k = 0; k + 1 < n; ++k) sum += rule(cut[k], cut[k + 1]);
        value_[j] = sum;
      }
      depth[j] = q.sigma_t * ((v - q.tmin) + Length(sq.point - q.camera_origin));
    }
    // Transmittance relative to the nearest node, so it underflows only where it is negligible.
    Real least = *std::min_element(depth.begin(), depth.begin() + count_);
    for (int j = 0; j < count_; ++j) value_[j] *= std::exp(least - depth[j]);
    Real largest = *std::max_element(value_.begin(), value_.begin() + count_);
    if (!(largest > 0) || !std::isfinite(largest)) {
      value_.fill(1);
      return;
    }
    for (Real& x : value_) x = std::max(x, kRelativeFloor * largest);
  }

  VrlPoint<Real> vp_;
  bool valid_ = false;
  int count_ = kNodes;
  std::array<Real, kMax> xi_, value_;  // the fit's nodes and values while it is built
  PiecewiseLinear<Real, kMax> fit_;     // over xi
};

// Its entry in the run-time sampler tables (method.hpp).
struct VrlMarginalEntry {
  static constexpr std::string_view kName = "marginal";
  template <typename Real>
  using Sampler = VrlMarginal<Real>;
};

}  // namespace vrlis
