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
// camera step's angle interval. Then
//   pdf(v) = p1(v) PL(P1(v)) / Int PL,   sample(u) = P1^-1(PL^-1(u)).
// Node values are floored at kRelativeFloor x their largest, so the density is positive
// wherever the integrand is and a poor estimate costs at most a bounded factor in variance.
// The fit costs kNodes (VrlPoint sample + angle domain + kRule target evaluations).
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

#include "../angle/full_product.hpp"
#include "novak.hpp"
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

template <typename R = float, int kNodes = 8, int kRule = 3, bool kSplit = true>
class VrlMarginal {
  static_assert(kNodes >= 2, "a piecewise-linear density needs two nodes");
  static_assert(kRule >= 1 && kRule <= 3, "Gauss-Legendre rules of 1 to 3 points");

 public:
  using Real = R;
  static constexpr int kNodeCount = kNodes;
  static constexpr Real kRelativeFloor = Real(0.02);

  explicit VrlMarginal(const VrlMarginalQuery<Real>& q) : vp_(q.vrl_point_query()) {
    valid_ = vp_.valid() && std::isfinite(q.camera_length) && q.camera_length >= 0 && std::abs(q.g) < 1 &&
             std::isfinite(q.sigma_t) && q.sigma_t >= 0;
    value_.fill(1);
    if (valid_ && q.camera_length > 0) Fit(q);
    Accumulate();
  }

  bool valid() const { return valid_; }
  const VrlPoint<Real>& vrl_point() const { return vp_; }

  Real sample(Real u) const {
    if (!valid_) return kNaN;
    return vp_.sample(SampleXi(u));
  }

  Real pdf(Real v) const {
    if (!valid_) return 0;
    Real p1 = vp_.pdf(v);
    if (!(p1 > 0)) return 0;
    return p1 * Lerp(vp_.invert(v)) / total_;
  }

  Real invert(Real v) const {
    if (!valid_) return kNaN;
    return Clamp(CdfXi(vp_.invert(v)), Real(0), Real(1));
  }

  // The fitted density over xi = VrlPoint.invert(v) (for studies): value(xi) / total.
  Real xi_density(Real xi) const { return Lerp(xi) / total_; }
  static constexpr Real node(int j) { return Real(j) / Real(kNodes - 1); }

 private:
  static constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
  static constexpr Real kStep = Real(1) / Real(kNodes - 1);

  void Fit(const VrlMarginalQuery<Real>& q) {
    // Gauss-Legendre on [0, 1].
    constexpr Real x2 = Real(0.21132486540518711775), x3 = Real(0.11270166537925831148);
    const Real xs[3] = {kRule == 1 ? Real(0.5) : kRule == 2 ? x2 : x3, kRule == 2 ? 1 - x2 : Real(0.5), 1 - x3};
    const Real ws[3] = {kRule == 1 ? Real(1) : kRule == 2 ? Real(0.5) : Real(5) / 18,
                        kRule == 2 ? Real(0.5) : Real(8) / 18, Real(5) / 18};
    SegmentQuery<Real> sq;
    sq.origin = q.camera_origin;
    sq.dir = q.camera_dir;
    sq.tmin = 0;
    sq.tmax = q.camera_length;
    sq.g = q.g;
    sq.lobe = {LobeKind::HenyeyGreenstein, q.dir, q.g};
    sq.sigma_t = q.sigma_t;
    std::array<Real, kNodes> depth;
    for (int j = 0; j < kNodes; ++j) {
      Real v = vp_.sample(node(j));
      sq.point = q.origin + v * q.dir;
      AngleDomain<Real> dom(sq);
      FullProductTarget<Real> target(sq, dom);
      Real width = dom.width(), peak = target.point_peak();
      auto rule = [&](Real a, Real b) {
        Real sum = 0;
        for (int i = 0; i < kRule; ++i) sum += ws[i] * target(a + xs[i] * (b - a));
        return (b - a) * sum;
      };
      // A point lobe peaking inside the interval: one rule on each side of the peak.
      bool split = kSplit && !target.point_lobe_flat() && peak > 0 && peak < width;
      value_[j] = split ? rule(Real(0), peak) + rule(peak, width) : rule(Real(0), width);
      depth[j] = q.sigma_t * ((v - q.tmin) + Length(sq.point - q.camera_origin));
    }
    // Transmittance relative to the nearest node, so it underflows only where it is negligible.
    Real least = *std::min_element(depth.begin(), depth.end());
    for (int j = 0; j < kNodes; ++j) value_[j] *= std::exp(least - depth[j]);
    Real largest = *std::max_element(value_.begin(), value_.end());
    if (!(largest > 0) || !std::isfinite(largest)) {
      value_.fill(1);
      return;
    }
    for (Real& x : value_) x = std::max(x, kRelativeFloor * largest);
  }

  void Accumulate() {
    cdf_[0] = 0;
    for (int j = 0; j + 1 < kNodes; ++j) cdf_[j + 1] = cdf_[j] + (value_[j] + value_[j + 1]) / 2 * kStep;
    total_ = cdf_[kNodes - 1];
  }

  int Interval(Real xi) const {
    int j = static_cast<int>(Clamp(xi, Real(0), Real(1)) * Real(kNodes - 1));
    return std::min(j, kNodes - 2);
  }

  Real Lerp(Real xi) const {
    int j = Interval(xi);
    Real s = Clamp((xi - node(j)) * Real(kNodes - 1), Real(0), Real(1));
    return value_[j] + s * (value_[j + 1] - value_[j]);
  }

  Real CdfXi(Real xi) const {
    int j = Interval(xi);
    Real s = Clamp((xi - node(j)) * Real(kNodes - 1), Real(0), Real(1));
    return (cdf_[j] + (value_[j] + (value_[j] + s * (value_[j + 1] - value_[j]))) / 2 * s * kStep) / total_;
  }

  Real SampleXi(Real u) const {
    Real target = u * total_;
    int j = 0;
    while (j < kNodes - 2 && !(cdf_[j + 1] > target)) ++j;
    Real area = cdf_[j + 1] - cdf_[j];
    Real w = area > 0 ? Clamp((target - cdf_[j]) / area, Real(0), Real(1)) : Real(0);
    return Clamp(node(j) + SampleLinear(w, value_[j], value_[j + 1]) * kStep, Real(0), Real(1));
  }

  VrlPoint<Real> vp_;
  bool valid_ = false;
  std::array<Real, kNodes> value_, cdf_;
  Real total_ = 1;
};

}  // namespace vrlis
