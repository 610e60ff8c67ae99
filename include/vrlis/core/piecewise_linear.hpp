#pragma once
// A piecewise-linear density: nodes x_0 <= ... <= x_{n-1}, non-negative values f_j at them,
// linear in between (the construction of Novák et al. 2012, used by Novak, FullProduct and
// VrlMarginal). One interval search serves sampling (over the running areas) and
// evaluation (over the nodes); inside an interval the linear density is inverted in closed
// form. Equal nodes make an interval of zero area that is never sampled.
#include <array>
#include <cmath>

#include "math.hpp"
#include "query.hpp"

namespace vrlis {

// a + s (b - a).
template <typename Real>
Real Lerp(Real s, Real a, Real b) { return a + s * (b - a); }

// The s in [0, 1] whose CDF under the density proportional to Lerp(s, f0, f1) is v: the
// root of (f1 - f0) s^2 / 2 + f0 s = v (f0 + f1) / 2 in the form that does not cancel.
// Numerator and denominator both grow with v, so in float their rounding can make s step
// back by an ulp as v grows (and t, through a steep map from the angle, by many); float
// evaluates it in double, where such a step is far below float's ulp.
template <typename Real>
Real SampleLinear(Real v, Real f0, Real f1) {
  using W = Widened<Real>;
  W a = f0, b = f1, denom = a + std::sqrt(a * a + W(v) * (b * b - a * a));
  return denom > 0 ? Real(Clamp(W(v) * (a + b) / denom, W(0), W(1))) : v;
}

// The largest j in [0, count - 2] with a[j] <= x (0 if there is none), for a nondecreasing a.
template <typename Real, std::size_t N>
int FindInterval(const std::array<Real, N>& a, int count, Real x) {
  int lo = 0, hi = count - 2;
  while (lo < hi) {
    int mid = (lo + hi + 1) / 2;
    if (a[mid] <= x) lo = mid; else hi = mid - 1;
  }
  return lo;
}

template <typename Real, int N>
class PiecewiseLinear {
  static_assert(N >= 2, "a piecewise-linear density needs two nodes");

 public:
  // A uniform density on [0, 1].
  PiecewiseLinear() : PiecewiseLinear({Real(0), Real(1)}, {Real(1), Real(1)}, 2) {}

  // The first `count` (2 <= count <= N) nodes and values. Values must be finite and >= 0,
  // with a positive area (the caller's fit guarantees it).
  PiecewiseLinear(const std::array<Real, N>& nodes, const std::array<Real, N>& values, int count = N)
      : count_(count), node_(nodes), value_(values) {
    // From the arguments, not the members just copied: no load waits on those stores.
    area_[0] = 0;
    for (int j = 0; j + 1 < count; ++j)
      area_[j + 1] = area_[j] + (values[j] + values[j + 1]) / 2 * (nodes[j + 1] - nodes[j]);
  }

  int count() const { return count_; }
  Real node(int j) const { return node_[j]; }
  Real value(int j) const { return value_[j]; }
  Real integral() const { return area_[count_ - 1]; }

  Real sample(Real u) const { return sample_pdf(u).t; }

  // A sample and its density, the density from the interval and position sampling found.
  SegmentSample<Real> sample_pdf(Real u) const {
    Real target = u * integral();
    int j = FindInterval(area_, count_, target);
    Real area = area_[j + 1] - area_[j];
    Real v = area > 0 ? Clamp((target - area_[j]) / area, Real(0), Real(1)) : Real(0);
    Real s = SampleLinear(v, value_[j], value_[j + 1]);
    Real x = Clamp(node_[j] + s * (node_[j + 1] - node_[j]), node_[0], node_[count_ - 1]);
    return {x, Lerp(s, value_[j], value_[j + 1]) / integral()};
  }

  // Zero outside [x_0, x_{n-1}].
  Real pdf(Real x) const {
    if (!(x >= node_[0] && x <= node_[count_ - 1])) return 0;
    int j = FindInterval(node_, count_, x);
    return Lerp(Within(x, j), value_[j], value_[j + 1]) / integral();
  }

  Real cdf(Real x) const {
    if (!(x > node_[0])) return 0;
    if (!(x < node_[count_ - 1])) return 1;
    int j = FindInterval(node_, count_, x);
    Real s = Within(x, j);
    Real partial = (value_[j] + Lerp(s, value_[j], value_[j + 1])) / 2 * s * (node_[j + 1] - node_[j]);
    return Clamp((area_[j] + partial) / integral(), Real(0), Real(1));
  }

 private:
  // The position of x inside interval j, in [0, 1] (0 for an empty interval).
  Real Within(Real x, int j) const {
    Real span = node_[j + 1] - node_[j];
    return span > 0 ? Clamp((x - node_[j]) / span, Real(0), Real(1)) : Real(0);
  }

  int count_;
  std::array<Real, N> node_, value_, area_;
};

}  // namespace vrlis
