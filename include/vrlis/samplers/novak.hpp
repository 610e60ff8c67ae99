#pragma once
// Novák et al. 2012, anisotropic camera-segment sampling: a piecewise-linear approximation
// of the phase product over kNodes nodes in the angle domain (section 4 of the maths note).
//
// If the point lobe's peak lies inside the interval the nodes are split there, and on each
// side they follow a cosine-warped spacing, dense near both ends of the side. An interval
// is chosen by its trapezoid area, then the linear density inside it is inverted.
#include <algorithm>
#include <array>
#include <string_view>

#include "../angle/full_product.hpp"
#include "../angle/segment_sampler.hpp"

namespace vrlis {

// The u in [0, 1] with density proportional to lerp(u, f0, f1) whose CDF is v (the stable
// root of the quadratic).
template <typename Real>
Real SampleLinear(Real v, Real f0, Real f1) {
  Real denom = f0 + std::sqrt(Sqr(f0) + v * (Sqr(f1) - Sqr(f0)));
  return denom > 0 ? Clamp(v * (f0 + f1) / denom, Real(0), Real(1)) : v;
}

// A piecewise-linear fit of a target over the angle domain. Target is constructed from
// (query, domain) and offers evaluate(deltas, values), point_lobe_flat(), point_peak() and
// kRelativeFloor (node values are raised to that fraction of the largest one).
template <typename R, int kNodes = 10, typename Target = PhaseProduct<R>>
class PiecewiseLinearAngle {
  static_assert(kNodes >= 3, "Novak's split needs at least one interval on each side");

 public:
  using Real = R;
  // Nodes are kept in units of the interval width and values in units of the largest, so
  // that neither tiny intervals nor tiny integrands push the areas into subnormals.
  PiecewiseLinearAngle(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom) : width_(dom.width()) {
    Target target(q, dom);
    Real peak = target.point_peak() / width_;
    if (!target.point_lobe_flat() && peak > 0 && peak < 1) {
      int split = static_cast<int>(std::lround(peak * (kNodes - 1)));
      split = Clamp(split, 1, kNodes - 2);
      PlaceWarped(0, Real(0), peak, split);
      PlaceWarped(split, peak, Real(1), kNodes - 1 - split);
    } else {
      PlaceWarped(0, Real(0), Real(1), kNodes - 1);
    }
    std::array<Real, kNodes> at;
    for (int j = 0; j < kNodes; ++j) at[j] = node_[j] * width_;
    target.evaluate(at, value_);
    Real largest = *std::max_element(value_.begin(), value_.end());
    if (largest > 0 && std::isfinite(largest))
      for (Real& v : value_) v = std::max(v / largest, Target::kRelativeFloor);
    Accumulate();
    if (!(cdf_[kNodes - 1] > 0) || !std::isfinite(cdf_[kNodes - 1])) {  // a target zero at every node
      value_.fill(1);
      Accumulate();
    }
  }

  Real sample(Real u) const {
    Real target = u * cdf_[kNodes - 1];
    int j = 0;
    while (j < kNodes - 2 && !(cdf_[j + 1] > target)) ++j;
    Real area = cdf_[j + 1] - cdf_[j];
    Real v = area > 0 ? Clamp((target - cdf_[j]) / area, Real(0), Real(1)) : Real(0);
    return (node_[j] + SampleLinear(v, value_[j], value_[j + 1]) * (node_[j + 1] - node_[j])) * width_;
  }

  Real pdf(Real delta) const {
    Real x = delta / width_;
    return Lerp(x, Interval(x)) / (cdf_[kNodes - 1] * width_);
  }

  Real cdf(Real delta) const {
    Real x = delta / width_;
    int j = Interval(x);
    Real partial = (value_[j] + Lerp(x, j)) / 2 * (x - node_[j]);
    return (cdf_[j] + partial) / cdf_[kNodes - 1];
  }

  // The node offsets (delta) of the fit.
  std::array<Real, kNodes> nodes() const {
    std::array<Real, kNodes> out;
    for (int j = 0; j < kNodes; ++j) out[j] = node_[j] * width_;
    return out;
  }

 private:
  // start + (end - start) (1 - cos(pi j / count)) / 2 for j = 0..count, written from index first.
  void PlaceWarped(int first, Real start, Real end, int count) {
    for (int j = 0; j <= count; ++j) node_[first + j] = start + (end - start) * WarpTable()[count][j];
    node_[first + count] = end;  // exact, so the two sides of a split share the peak node
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

  void Accumulate() {
    cdf_[0] = 0;
    for (int j = 0; j + 1 < kNodes; ++j) cdf_[j + 1] = cdf_[j] + (value_[j] + value_[j + 1]) / 2 * (node_[j + 1] - node_[j]);
  }

  // The interval [node_j, node_j+1] holding x (binary search).
  int Interval(Real x) const {
    int lo = 0, hi = kNodes - 2;
    while (lo < hi) {
      int mid = (lo + hi + 1) / 2;
      if (node_[mid] <= x) lo = mid; else hi = mid - 1;
    }
    return lo;
  }

  Real Lerp(Real x, int j) const {
    Real span = node_[j + 1] - node_[j];
    Real s = span > 0 ? Clamp((x - node_[j]) / span, Real(0), Real(1)) : Real(0);
    return value_[j] + s * (value_[j + 1] - value_[j]);
  }

  Real width_;
  std::array<Real, kNodes> node_, value_, cdf_;  // nodes in units of width_, values of the largest
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
