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
// point lobe's peak, and 3 (1 - |g|) plus the pole's distance from the end nearest the
// segment lobe's pole; for strong backward scattering also the point lobe's peak
// +- 3 (1 - |g|); without the cuts the rule misses |g| -> 1 spikes and the mean relative
// variance at |g| = 0.99 doubles). kClosest adds a node at the VRL point
// closest to the camera line (measured: no gain, so off by default). Then
//   pdf(v) = p1(v) PL(P1(v)) / Int PL,   sample(u) = P1^-1(PL^-1(u)).
// Node values are floored at kRelativeFloor x their largest, so the density is positive
// wherever the integrand is and a poor estimate costs at most a bounded factor in variance.
// The fit costs kNodes x (VrlPoint sample + angle domain + 1 to 5 pieces x kRule target
// evaluations), run as two loops over the nodes that vectorise in float (FitNodes), with the
// lanes' sines, cosines and exponentials to a fit's accuracy (core/lane_math.hpp's Accuracy);
// its time is vrlis_bench's VrlMarginal/step (docs/bench.md).
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

  // Step one for count (1 to kSize) VRLs against one camera segment, each a valid gather
  // query with it (SampleMediumGathers): out[i] is VrlMarginal({camera, vrls[i], medium})
  // .sample_pdf(u[i]) to rounding, or, where fitted is set and fitted[i] false, VrlPoint's
  // sample_pdf(u[i]) (a flat fit: no fit made). A run of equal VRLs (a split gather's
  // samples) is fitted once; the VRL points are SampleVrlPoints', in lanes over the gathers.
  template <int kSize>
  static void SampleLanes(ValidQuery, const RaySegment<Real>& camera, const Medium<Real>& medium,
                          const VrlSegment<Real>* vrls, int count, const Real* u, SegmentSample<Real>* out,
                          const bool* fitted = nullptr) {
    Real xi[kSize], xi_pdf[kSize];
    for (int first = 0, i = 0; first < count; first = i) {
      if (fitted && !fitted[first]) {
        xi[i] = u[i], xi_pdf[i] = 1;
        ++i;
        continue;
      }
      const VrlMarginal marginal(ValidQuery{}, MediumGatherQuery<Real>{camera, vrls[first], medium});
      for (; i < count && SameVrl(vrls[first], vrls[i]) && (!fitted || fitted[i]); ++i) {
        const SegmentSample<Real> s = marginal.fit_.sample_pdf(u[i]);
        xi[i] = s.t, xi_pdf[i] = s.pdf;
      }
    }
    SampleVrlPoints<kSize>(ValidQuery{}, camera, vrls, count, xi, out);
    for (int i = 0; i < count; ++i) out[i].pdf *= xi_pdf[i];
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

  // The node values: the marginal estimate over VrlPoint's density at each node. Without
  // anisotropy (g = 0) both lobes are flat and one piece serves; otherwise three, cut at the
  // point lobe's peak and at the pole's reach, or five below kNarrowCutsBelow.
  void Fit(const MediumGatherQuery<Real>& q, const std::array<Real, kMax>& xi, int count,
           std::array<Real, kMax>& value) const {
    if (q.medium.g == 0) {
      FitNodes<1, true>(q, xi, count, value);
    } else if constexpr (!kSplit) {
      FitNodes<1, false>(q, xi, count, value);
    } else if (q.medium.g < kNarrowCutsBelow) {
      FitNodes<5, false>(q, xi, count, value);
    } else {
      FitNodes<3, false>(q, xi, count, value);
    }
  }

  // Below this g the pieces are also cut a few lobe widths either side of the point lobe's
  // peak. Measured (vrlis_accuracy --pairs 64, FullProduct after VrlMarginal): without those
  // cuts the mean relative variance grows 1.4x at g = -0.9 and 3.8x at -0.99, and by at most
  // 3% at every g from -0.5 to 0.99, where they cost a fifth of the fit's time.
  static constexpr Real kNarrowCutsBelow = Real(-0.5);

  // The fit in two loops over the nodes, each branch-free so that it vectorises in float:
  // the first places each node's VRL point, reduces the camera segment to its angle domain
  // (detail::ReduceToAngles), shapes both lobes and cuts the rule's pieces; the second runs
  // the rule, kUsed pieces of kRule points, over all nodes at once. A node with fewer cuts
  // has empty pieces (zero width), so every node takes the same points. kIsotropic (g = 0):
  // both lobes are the constant 1 / (4 pi), and only the transmittance is shaped.
  template <int kUsed, bool kIsotropic>
  void FitNodes(const MediumGatherQuery<Real>& q, const std::array<Real, kMax>& xi, int count,
                std::array<Real, kMax>& value) const {
    // Gauss-Legendre on [0, 1].
    constexpr Real x2 = Real(0.21132486540518711775), x3 = Real(0.11270166537925831148);
    constexpr Real xs[3] = {kRule == 1 ? Real(0.5) : kRule == 2 ? x2 : x3, kRule == 2 ? 1 - x2 : Real(0.5), 1 - x3};
    constexpr Real ws[3] = {kRule == 1 ? Real(1) : kRule == 2 ? Real(0.5) : Real(5) / 18,
                            kRule == 2 ? Real(0.5) : Real(8) / 18, Real(5) / 18};
    const Real g = q.medium.g, sigma_t = q.medium.sigma_t, lobe = 3 * (1 - std::abs(g));
    const RaySegment<Real>& camera = q.camera;
    const Vec3<Real> camera_start = camera.at(camera.tmin);
    const detail::VrlPointDensity<Real>& density = vp_.density();
    const bool representable = vp_.representable();
    // One array per quantity (the layout vector loads want): the transmittance's pole and
    // scale, both lobes' rotations (their other parameters are the query's), the cuts.
    std::array<Real, kMax> depth, depth_scale, pole_sin, pole_cos, point_sin, point_cos, point_base, point_slope;
    std::array<std::array<Real, kMax>, kUsed + 1> cut;  // node j's pieces run from cut[k][j] to cut[k + 1][j]
    const Real turn = g < 0 ? kPi<Real> : Real(0);  // the point lobe peaks opposite its axis for g < 0
    for (int j = 0; j < kMax; ++j) {
      Real v = SelectLanes(representable, detail::SampleVrlPointDensity<true>(density, xi[j]).t, density.tmin);
      Vec3<Real> y = q.vrl.at(v);
      const detail::AngleFrame<Real> frame =
          detail::ReduceToAngles<true>(y, camera.origin, camera.dir, camera.tmin, camera.tmax);
      const Real lower = detail::PolesOf<true>(frame.tan_a).lower;
      const SinCosPair<Real> pole = SinCosLanes<Accuracy::Fit>(lower / 2);
      pole_sin[j] = pole.sin;
      pole_cos[j] = pole.cos;
      depth_scale[j] = sigma_t * frame.h / pole.cos;
      detail::LobeInPlane<Real> in_plane{};
      if constexpr (!kIsotropic) {
        in_plane = detail::ProjectLobe<true>(q.vrl.dir, frame.n, camera.dir, frame.tan_a, frame.on_line);
        const auto point =
            detail::LobeShape<Real>::Of(g, in_plane.r, in_plane.one_minus_r, SinCosLanes<Accuracy::Fit>(in_plane.theta_e / 2));
        point_sin[j] = point.from_sin;
        point_cos[j] = point.from_cos;
        point_base[j] = point.base;
        point_slope[j] = point.slope;
      }
      depth[j] = sigma_t * (v + SqrtLanes(Dot(y - camera_start, y - camera_start)));
      const Real width = frame.width;
      cut[0][j] = 0;
      cut[kUsed][j] = width;
      if constexpr (kUsed > 1) {
        static_assert(kUsed == 3 || kUsed == 5, "two or four interior cuts");
        // Pieces that isolate the lobes' peaks, so the rule sees them: the point lobe's peak
        // (if inside; PhaseProduct::point_peak), with five pieces also a few lobe widths
        // (1 - |g|) on either side, and the segment lobe's peak, a pole at or beyond one end
        // (its distance: -lower, or upper - width with upper = lower + pi), with a few lobe
        // widths plus that distance. A cut that is not made sits at 0; a sorting network puts
        // them in order.
        Real peak = detail::NearestPeak(in_plane.theta_e + turn, width);
        bool inside = (in_plane.r > 0) & (peak > 0) & (peak < width);
        Real reach = lobe + SelectLanes(g > 0, -lower, lower + kPi<Real> - width);
        Real at_peak = SelectLanes(inside, peak, Real(0));
        Real at_pole = SelectLanes(reach < width / 2, SelectLanes(g > 0, reach, width - reach), Real(0));
        std::array<Real, kUsed - 1> c;
        auto order = [&c](int a, int b) {
          Real lo = SelectLanes(c[b] < c[a], c[b], c[a]), hi = SelectLanes(c[b] < c[a], c[a], c[b]);
          c[a] = lo;
          c[b] = hi;
        };
        if constexpr (kUsed == 5) {
          c = {SelectLanes(inside & (peak - lobe > 0), peak - lobe, Real(0)), at_peak,
               SelectLanes(inside & (peak + lobe < width), peak + lobe, Real(0)), at_pole};
          order(0, 1), order(2, 3), order(0, 2), order(1, 3), order(1, 2);
        } else {
          c = {at_peak, at_pole};
          order(0, 1);
        }
        for (int k = 0; k < kUsed - 1; ++k) cut[k + 1][j] = c[k];
      }
    }
    // The rule, node by node in lanes; the segment lobe's rotation is the pole's.
    const Real point_scale = detail::LobeShape<Real>::Of(g, 1, 0, {}).scale;  // the lobes' g is the same
    // Cuts not made sort to the front as empty pieces; skip those empty at every node.
    int first = 0;
    while (first + 1 < kUsed && *std::max_element(cut[first + 1].begin(), cut[first + 1].end()) == 0) ++first;
    std::array<Real, kMax> sum{};
    for (int k = first; k < kUsed; ++k) {
      const std::array<Real, kMax>& from = cut[k];
      const std::array<Real, kMax>& to = cut[k + 1];
      for (int i = 0; i < kRule; ++i) {
        for (int j = 0; j < kMax; ++j) {
          Real a = from[j], b = to[j], delta = a + xs[i] * (b - a);
          SinCosPair<Real> half = SinCosLanes<Accuracy::Fit>(delta / 2), pole{pole_sin[j], pole_cos[j]};
          Real transmittance = SelectLanes(
              depth_scale[j] > 0, detail::SegmentTransmittance<Accuracy::Fit>(half, pole, depth_scale[j]), Real(1));
          Real lobes = point_scale * point_scale;
          if constexpr (!kIsotropic) {
            const detail::LobeShape<Real> point{point_sin[j], point_cos[j], point_base[j], point_slope[j], point_scale},
                segment = detail::LobeShape<Real>::Of(g, 1, 0, pole);
            lobes = detail::LobeProduct<Accuracy::Fit>(segment, point, half);
          }
          sum[j] += ws[i] * (b - a) * lobes * transmittance;
        }
      }
    }
    // Transmittance relative to the nearest node, so it underflows only where it is negligible.
    Real least = *std::min_element(depth.begin(), depth.begin() + count);
    for (int j = 0; j < kMax; ++j) value[j] = sum[j] * ExpLanes<Accuracy::Fit>(least - depth[j]);  // past count: unused
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
  template <typename Real>
  using Sampler = VrlMarginal<Real>;
};

}  // namespace vrlis
