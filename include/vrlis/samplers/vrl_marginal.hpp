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
// factor exp(-sigma_t |y - x(tmin)|) by which it is normalised).
//
// So M / p1 is bounded and smooth: r(v) = T(v) exp(-sigma_t |y(v) - x(tmin)|) Int F dtheta.
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
// The camera segment is the gather's [tmin, tmax], transmittance measured from x(tmin);
// tmax may be +infinity: the angle domain maps it to a bounded interval and transmittance
// makes the integrand vanish towards theta = pi/2, so the estimates stay finite.
//
// Contract (same as VrlPoint): error() is Validate(MediumGatherQuery); when it is not
// QueryError::None, valid() is false, sample() and invert() return NaN and pdf() returns 0.
// A VRL shorter than min<Real> / epsilon<Real> samples 0 with pdf 0. A zero-length camera
// segment (the integrand is 0) or a marginal estimate that underflows at every node falls
// back to VrlPoint's density. Parallel and intersecting lines are handled by VrlPoint and
// AngleDomain (finite, positive estimates).
#include <algorithm>
#include <array>
#include <limits>
#include <string_view>

#include "../angle/full_product.hpp"
#include "../core/piecewise_linear.hpp"
#include "vrl_point.hpp"

namespace vrlis {

template <typename R = float, int kNodes = 8, int kRule = 2, bool kSplit = true, bool kClosest = false>
class VrlMarginal {
  static_assert(kNodes >= 2, "a piecewise-linear density needs two nodes");
  static_assert(kRule >= 1 && kRule <= 3, "Gauss-Legendre rules of 1 to 3 points");

 public:
  using Real = R;
  static constexpr int kNodeCount = kNodes;  // uniform nodes; plus the closest point (kClosest)
  static constexpr Real kRelativeFloor = Real(0.02);

  // Step one of a medium-to-medium gather; the camera segment may be unbounded (tmax = +inf).
  explicit VrlMarginal(const MediumGatherQuery<Real>& q) : VrlMarginal(q, VrlPoint<Real>(q)) {}
  // The same for a gather query the caller has validated.
  VrlMarginal(ValidQuery, const MediumGatherQuery<Real>& q) : VrlMarginal(q, VrlPoint<Real>(ValidQuery{}, q)) {}

 private:
  VrlMarginal(const MediumGatherQuery<Real>& q, const VrlPoint<Real>& vp) : vp_(vp) {
    if (!valid()) return;
    std::array<Real, kMax> xi, value;
    int count = PlaceNodes(q, xi);
    value.fill(1);
    if (q.camera.tmax > q.camera.tmin) Fit(q, xi, count, value);
    fit_ = PiecewiseLinear<Real, kMax>(xi, value, count);
  }

 public:
  // The gather query's validation (VrlPoint's, which validates the whole query).
  bool valid() const { return vp_.valid(); }
  QueryError error() const { return vp_.error(); }
  const VrlPoint<Real>& vrl_point() const { return vp_; }

  Real sample(Real u) const { return sample_pdf(u).t; }

  Real pdf(Real v) const {
    if (!valid()) return 0;
    Real p1 = vp_.pdf(v);
    if (!(p1 > 0)) return 0;
    return p1 * fit_.pdf(vp_.invert(v));
  }

  // The density is the product of the two warps' densities at the sampled xi and v.
  SegmentSample<Real> sample_pdf(Real u) const {
    if (!valid()) return {kNaN, 0};
    SegmentSample<Real> xi = fit_.sample_pdf(u);
    SegmentSample<Real> v = vp_.sample_pdf(xi.t);
    return {v.t, v.pdf * xi.pdf};
  }

  Real invert(Real v) const {
    if (!valid()) return kNaN;
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
  // Returns the number of nodes.
  int PlaceNodes(const MediumGatherQuery<Real>& q, std::array<Real, kMax>& xi) const {
    for (int j = 0; j < kMax; ++j) xi[j] = j < kNodes ? node(j) : Real(1);
    if constexpr (kClosest) {
      Vec3<Real> cr = Cross(q.vrl.dir, q.camera.dir), d = q.camera.origin - q.vrl.origin;
      Real sin2 = Dot(cr, cr);
      if (!(sin2 > Real(1e-6))) return kNodes;
      Real v0 = (Dot(d, q.vrl.dir) - Dot(d, q.camera.dir) * Dot(q.vrl.dir, q.camera.dir)) / sin2;
      if (!(v0 > 0 && v0 < q.vrl.length)) return kNodes;
      Real x0 = vp_.invert(v0);
      int j = std::min(static_cast<int>(x0 * Real(kNodes - 1)), kNodes - 2);
      Real gap = Real(0.05) / Real(kNodes - 1);
      if (!(x0 - xi[j] > gap && xi[j + 1] - x0 > gap)) return kNodes;
      for (int k = kNodes; k > j + 1; --k) xi[k] = xi[k - 1];
      xi[j + 1] = x0;
      return kNodes + 1;
    }
    return kNodes;
  }

  // The node values: the marginal estimate over VrlPoint's density at each node.
  void Fit(const MediumGatherQuery<Real>& q, const std::array<Real, kMax>& xi, int count,
           std::array<Real, kMax>& value) const {
    // Gauss-Legendre on [0, 1].
    constexpr Real x2 = Real(0.21132486540518711775), x3 = Real(0.11270166537925831148);
    const Real xs[3] = {kRule == 1 ? Real(0.5) : kRule == 2 ? x2 : x3, kRule == 2 ? 1 - x2 : Real(0.5), 1 - x3};
    const Real ws[3] = {kRule == 1 ? Real(1) : kRule == 2 ? Real(0.5) : Real(5) / 18,
                        kRule == 2 ? Real(0.5) : Real(8) / 18, Real(5) / 18};
    const Real g = q.medium.g, sigma_t = q.medium.sigma_t;
    SegmentQuery<Real> sq = MediumToMediumQuery(q.camera.origin, q.camera.dir, q.camera.tmin, q.camera.tmax,
                                                q.vrl.origin, q.vrl.dir, g, sigma_t);
    const Vec3<Real> camera_start = q.camera.at(q.camera.tmin);
    std::array<Real, kMax> depth;
    for (int j = 0; j < count; ++j) {
      Real v = vp_.sample(xi[j]);
      sq.point = q.vrl.at(v);
      AngleDomain<Real> dom(sq);
      FullProductTarget<Real> target(sq, dom);
      Real width = dom.width(), peak = target.point_peak();
      auto rule = [&](Real a, Real b) {
        Real sum = 0;
        for (int i = 0; i < kRule; ++i) sum += ws[i] * target(a + xs[i] * (b - a));
        return (b - a) * sum;
      };
      if constexpr (!kSplit) {
        value[j] = rule(Real(0), width);
      } else {
        // Pieces that isolate the lobes' peaks, so the rule sees them: the point lobe's peak
        // (if inside) with a few lobe widths (1 - |g|) on either side, and the segment lobe's
        // peak, a pole at or beyond one end, with a few lobe widths plus its distance.
        std::array<Real, 6> cut;
        int n = 0;
        cut[n++] = 0;
        Real lobe = 3 * (1 - std::abs(g));
        if (!target.point_lobe_flat() && peak > 0 && peak < width) {
          if (peak - lobe > 0) cut[n++] = peak - lobe;
          cut[n++] = peak;
          if (peak + lobe < width) cut[n++] = peak + lobe;
        }
        if (g != 0) {
          Real pole = kPi<Real> / 2 + (g > 0 ? dom.theta_a() : -dom.theta_b());  // beyond its end
          Real reach = lobe + pole;
          if (reach < width / 2) cut[n++] = g > 0 ? reach : width - reach;
        }
        cut[n++] = width;
        std::sort(cut.begin(), cut.begin() + n);
        Real sum = 0;
        for (int k = 0; k + 1 < n; ++k) sum += rule(cut[k], cut[k + 1]);
        value[j] = sum;
      }
      depth[j] = sigma_t * (v + Length(sq.point - camera_start));
    }
    // Transmittance relative to the nearest node, so it underflows only where it is negligible.
    Real least = *std::min_element(depth.begin(), depth.begin() + count);
    for (int j = 0; j < count; ++j) value[j] *= std::exp(least - depth[j]);
    Real largest = *std::max_element(value.begin(), value.begin() + count);
    if (!(largest > 0) || !std::isfinite(largest)) {
      value.fill(1);
      return;
    }
    for (Real& x : value) x = std::max(x, kRelativeFloor * largest);
  }

  VrlPoint<Real> vp_;
  PiecewiseLinear<Real, kMax> fit_;  // over xi
};

// Its entry in the run-time sampler tables (method.hpp).
struct VrlMarginalEntry {
  static constexpr std::string_view kName = "marginal";
  static constexpr bool kOwn = true;
  template <typename Real>
  using Sampler = VrlMarginal<Real>;
};

}  // namespace vrlis
