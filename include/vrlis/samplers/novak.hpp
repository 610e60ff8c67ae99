#pragma once
// Novák et al. 2012, anisotropic camera-segment sampling: a piecewise-linear approximation
// of the phase product over kNodes nodes in the angle domain (docs/maths.md#novak).
//
// If the point lobe's peak lies inside the interval the nodes are split there, and on each
// side they follow a cosine-warped spacing, dense near both ends of the side; the density
// is core/piecewise_linear.hpp's. (FullProduct splits at its target's peaks too.)
#include <algorithm>
#include <array>
#include <string_view>

#include "../angle/full_product.hpp"
#include "../angle/segment_sampler.hpp"
#include "../core/piecewise_linear.hpp"

namespace vrlis {

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
  static constexpr bool kBaseline = true;
  template <typename Real>
  using Sampler = Novak<Real>;
};

}  // namespace vrlis
