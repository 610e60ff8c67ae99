#pragma once
// Novák et al. 2012, anisotropic camera-segment sampling: a piecewise-linear approximation
// of the phase product over kNodes nodes in the angle domain (docs/maths.md#novak).
//
// If the point lobe's peak lies inside the interval the nodes are split there, and on each
// side they follow a cosine-warped spacing, dense near both ends of the side; the density
// is core/piecewise_linear.hpp's. (FullProduct splits at its target's peaks too.)
#include <algorithm>
#include <array>
#include <limits>
#include <string_view>
#include <type_traits>

#include "../angle/full_product.hpp"
#include "../angle/segment_sampler.hpp"
#include "../core/piecewise_linear.hpp"

namespace vrlis {

namespace detail {
// Target::Lanes<kSize> as `type`, absent (not an error) where Target has no form in lanes.
template <typename Target, int kSize, typename = void>
struct LanesOf {};
template <typename Target, int kSize>
struct LanesOf<Target, kSize, std::void_t<typename Target::template Lanes<kSize>>> {
  using type = typename Target::template Lanes<kSize>;
};
}  // namespace detail

// A piecewise-linear fit of a target over the angle domain. Target is constructed from
// (query, domain) and offers evaluate(deltas, values), splits(points) (the offsets where a
// node must sit, at most two) and kRelativeFloor (node values are raised to that fraction
// of the largest one).
template <typename R, int kNodes = 10, typename Target = PhaseProduct<R>>
class PiecewiseLinearAngle {
  static_assert(kNodes >= 3, "a split needs at least one interval on each side");

 public:
  using Real = R;
  // Nodes are kept in units of the interval width and values in units of the largest, so
  // that neither tiny intervals nor tiny integrands push the areas into subnormals.
  PiecewiseLinearAngle(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom)
      : PiecewiseLinearAngle(Target(q, dom), dom.width()) {}
  // The fit of a target already built (by a caller that needed it for something else).
  PiecewiseLinearAngle(const Target& target, Real width) : width_(width), fit_(Fit(target, width)) {}

  Real sample(Real u) const { return fit_.sample(u) * width_; }
  // Offsets are in [0, width] up to the rounding of offset_at, hence the clamp.
  Real pdf(Real delta) const { return fit_.pdf(Clamp(delta / width_, Real(0), Real(1))) / width_; }
  Real cdf(Real delta) const { return fit_.cdf(delta / width_); }
  SegmentSample<Real> sample_pdf(Real u) const {
    SegmentSample<Real> s = fit_.sample_pdf(u);
    return {s.t * width_, s.pdf / width_};
  }

  // A batch's fits, each sampled once, in vector lanes: lane i of `target` (a
  // Target::Lanes<kSize>, built for lanes [0, lanes)) fitted as above and sampled at u[i],
  // out[i] what sample_pdf(u[i]) returns, to rounding. One loop over the lanes per step
  // (the splits, each node's offset and value, the normalisation, the areas, the interval
  // search), then the closed-form inversion one lane at a time (in double for float).
  template <int kSize>
  using TargetLanes = typename detail::LanesOf<Target, kSize>::type;  // none if Target has no Lanes
  template <int kSize>
  static void SampleLanes(const TargetLanes<kSize>& target, const Real* u, int lanes, SegmentSample<Real>* out) {
    constexpr int kLast = kNodes - 1;
    constexpr Real kInf = std::numeric_limits<Real>::infinity();
    // Each lane's sides (as Fit): side k in [0, 2] runs from node last_k-1 (offset end_k-1) to
    // node last_k (offset end_k), with last_-1 = 0, end_-1 = 0, last_2 = kLast, end_2 = 1; a lane
    // with fewer splits has its unused sides end at the last node.
    Real split[2][kSize];
    int count[kSize], last0[kSize], last1[kSize];
    Real end0[kSize], end1[kSize];
    target.splits(lanes, split, count);
    auto side_end = [&](int k, int i, int n, int first, int& last) {
      const bool real = k < n;
      const Real e = SelectLanes(real, split[k][i] / target.width[i], Real(1));
      const Real safe = SelectLanes((e >= 0) & (e <= 1), e, Real(0));  // (NaN in a lane left unused)
      const int rounded = static_cast<int>(safe * kLast + Real(0.5));
      last = real ? std::min(std::max(rounded, first + 1), kLast - (n - k)) : kLast;
      return e;
    };
    for (int i = 0; i < lanes; ++i) {
      const int n = std::min(count[i], kNodes - 2);
      end0[i] = side_end(0, i, n, 0, last0[i]);
      end1[i] = side_end(1, i, n, last0[i], last1[i]);
    }
    Real node[kNodes][kSize], value[kNodes][kSize];
    const Real* warp = WarpTable()[0].data();  // row-major, kNodes per row
    for (int j = 0; j < kNodes; ++j) {
      Real at[kSize];
      for (int i = 0; i < lanes; ++i) {
        const bool past0 = j > last0[i], past1 = j > last1[i];
        const int first = past1 ? last1[i] : past0 ? last0[i] : 0, to = past1 ? kLast : past0 ? last1[i] : last0[i];
        const Real start = SelectLanes(past1, end1[i], SelectLanes(past0, end0[i], Real(0)));
        const Real stop = SelectLanes(past1, Real(1), SelectLanes(past0, end1[i], end0[i]));
        const Real warped = start + (stop - start) * warp[(to - first) * kNodes + (j - first)];
        node[j][i] = SelectLanes(j == to, stop, warped);
        at[i] = node[j][i] * target.width[i];
      }
      target.template evaluate<Accuracy::Fit>(lanes, at, value[j]);
    }
    // Values in units of the largest, above the floor; the running areas.
    Real largest[kSize], area[kNodes][kSize];
    for (int i = 0; i < lanes; ++i) largest[i] = value[0][i], area[0][i] = 0;
    for (int j = 1; j < kNodes; ++j)
      for (int i = 0; i < lanes; ++i) largest[i] = SelectLanes(largest[i] < value[j][i], value[j][i], largest[i]);
    for (int j = 0; j < kNodes; ++j)
      for (int i = 0; i < lanes; ++i) {
        const Real relative = value[j][i] / largest[i];
        const bool scaled = (largest[i] > 0) & (largest[i] < kInf);
        value[j][i] = SelectLanes(scaled, SelectLanes(relative < Target::kRelativeFloor, Target::kRelativeFloor, relative),
                                  value[j][i]);
      }
    for (int j = 0; j < kLast; ++j)
      for (int i = 0; i < lanes; ++i)
        area[j + 1][i] = area[j][i] + (value[j][i] + value[j + 1][i]) / 2 * (node[j + 1][i] - node[j][i]);
    const Real* integral = area[kLast];
    for (int i = 0; i < lanes; ++i)
      if (!(integral[i] > 0 && integral[i] < kInf)) {  // a target zero (or NaN) at every node: uniform, as Fit
        for (int j = 0; j < kNodes; ++j) value[j][i] = 1;
        for (int j = 0; j < kLast; ++j) area[j + 1][i] = area[j][i] + (node[j + 1][i] - node[j][i]);
      }
    // PiecewiseLinear::sample_pdf: the interval j as the count of running areas at or below
    // the target (FindInterval), then its ends picked by selects.
    Real target_area[kSize], a0[kSize], a1[kSize], f0[kSize], f1[kSize], x0[kSize], x1[kSize];
    int interval[kSize];
    for (int i = 0; i < lanes; ++i) target_area[i] = u[i] * integral[i], interval[i] = 0;
    for (int m = 1; m < kLast; ++m)
      for (int i = 0; i < lanes; ++i) interval[i] += area[m][i] <= target_area[i];
    for (int i = 0; i < lanes; ++i) a0[i] = a1[i] = f0[i] = f1[i] = x0[i] = x1[i] = 0;
    for (int m = 0; m < kLast; ++m)
      for (int i = 0; i < lanes; ++i) {
        const bool here = interval[i] == m;
        a0[i] = SelectLanes(here, area[m][i], a0[i]), a1[i] = SelectLanes(here, area[m + 1][i], a1[i]);
        f0[i] = SelectLanes(here, value[m][i], f0[i]), f1[i] = SelectLanes(here, value[m + 1][i], f1[i]);
        x0[i] = SelectLanes(here, node[m][i], x0[i]), x1[i] = SelectLanes(here, node[m + 1][i], x1[i]);
      }
    Real v[kSize];
    for (int i = 0; i < lanes; ++i) {
      const Real width = a1[i] - a0[i];
      v[i] = SelectLanes(width > 0, PickClamp<true>((target_area[i] - a0[i]) / width, Real(0), Real(1)), Real(0));
    }
    for (int i = 0; i < lanes; ++i) {
      const Real s = SampleLinear(v[i], f0[i], f1[i]);
      const Real x = Clamp(x0[i] + s * (x1[i] - x0[i]), Real(0), Real(1));
      out[i] = {x * target.width[i], Lerp(s, f0[i], f1[i]) / integral[i] / target.width[i]};
    }
  }

  // The node offsets (delta) of the fit.
  std::array<Real, kNodes> nodes() const {
    std::array<Real, kNodes> out;
    for (int j = 0; j < kNodes; ++j) out[j] = fit_.node(j) * width_;
    return out;
  }

 private:
  // The fit in units of the width (built in place: a default-constructed member assigned
  // afterwards cost a store-forwarding stall per fit).
  static PiecewiseLinear<Real, kNodes> Fit(const Target& target, Real width) {
    std::array<Real, kNodes> node, value;
    // Each side of a split gets at least one interval, the rest in proportion to its width.
    std::array<Real, 2> splits;
    int n = std::min(target.splits(splits), kNodes - 2);
    Real start = 0;
    int first = 0;
    for (int k = 0; k <= n; ++k) {
      Real end = k < n ? splits[k] / width : Real(1);  // in (0, 1): rounds by adding a half
      int last = k < n ? Clamp(static_cast<int>(end * (kNodes - 1) + Real(0.5)), first + 1, kNodes - 1 - (n - k))
                       : kNodes - 1;
      PlaceWarped(node, first, start, end, last - first);
      start = end;
      first = last;
    }
    std::array<Real, kNodes> at;
    for (int j = 0; j < kNodes; ++j) at[j] = node[j] * width;
    target.template evaluate<Accuracy::Fit>(at, value);  // node values: core/lane_math.hpp's Accuracy
    Real largest = *std::max_element(value.begin(), value.end());
    if (largest > 0 && std::isfinite(largest))
      for (Real& v : value) v = std::max(v / largest, Target::kRelativeFloor);
    PiecewiseLinear<Real, kNodes> fit(node, value);
    if (!(fit.integral() > 0) || !std::isfinite(fit.integral())) {  // a target zero (or NaN) at every node
      value.fill(1);
      fit = PiecewiseLinear<Real, kNodes>(node, value);
    }
    return fit;
  }

  // start + (end - start) (1 - cos(pi j / count)) / 2 for j = 0..count, written from index first.
  static void PlaceWarped(std::array<Real, kNodes>& node, int first, Real start, Real end, int count) {
    for (int j = 0; j <= count; ++j) node[first + j] = start + (end - start) * WarpTable()[count][j];
    node[first + count] = end;  // exact, so the two sides of a split share the peak node
  }

  // (1 - cos(pi j / count)) / 2 = sin^2(pi j / (2 count)): fixed per node count, so computed once.
  static const std::array<std::array<Real, kNodes>, kNodes>& WarpTable() {
    static const auto table = [] {
      std::array<std::array<Real, kNodes>, kNodes> t{};
      for (int count = 1; count < kNodes; ++count)
        for (int j = 0; j <= count; ++j)
          t[count][j] = Real(Sqr(std::sin(3.14159265358979323846 * j / (2 * count))));
      return t;
    }();
    return table;
  }

  Real width_;
  PiecewiseLinear<Real, kNodes> fit_;  // over delta / width_, values in units of the largest
};

// Novák et al.: the phase product, 10 nodes as in the public implementation.
template <typename Real = float, int kNodes = 10>
using Novak = SegmentSampler<PiecewiseLinearAngle<Real, kNodes, PhaseProduct<Real>>>;

// Its entry in the run-time sampler tables (method.hpp).
struct NovakEntry {
  static constexpr std::string_view kName = "novak";
  template <typename Real>
  using Sampler = Novak<Real>;
};

}  // namespace vrlis
