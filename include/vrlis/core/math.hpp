#pragma once
// Small numeric helpers shared by every sampler.
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "lane_math.hpp"

namespace vrlis {

template <typename Real>
inline constexpr Real kPi = Real(3.14159265358979323846);

template <typename Real>
inline constexpr Real kInvPi = Real(0.31830988618379067154);

template <typename Real>
constexpr Real Sqr(Real x) { return x * x; }

template <typename Real>
Real SafeSqrt(Real x) { return std::sqrt(std::max(x, Real(0))); }

template <typename Real>
constexpr Real Clamp(Real x, Real lo, Real hi) { return std::min(std::max(x, lo), hi); }

// Clamp, in lanes by selects (std::min and std::max pass references, and arithmetic on
// their result kept GCC from vectorising a loop); NaN kept either way.
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline Real PickClamp(Real x, Real lo, Real hi) {
  if constexpr (kLanes) {
    return SelectLanes(x < lo, lo, SelectLanes(hi < x, hi, x));
  } else {
    return Clamp(x, lo, hi);
  }
}

// The precision a float computation runs in where rounding would reverse the order of
// neighbouring samples: double for float.
template <typename Real>
using Widened = std::conditional_t<std::is_same_v<Real, float>, double, Real>;

// asinh(xb) - asinh(xa) for xb = xa + dx, dx >= 0, is log1p of this argument, given
// sa = sqrt(1 + xa^2) and sb = sqrt(1 + xb^2); written without the cancellation of the naive
// difference when both are large and of one sign: mirrored so that the larger magnitude
// is positive, then asinh(xb) - asinh(xa) = log((xb + sb) / (xa + sa)) with
// xb + sb - (xa + sa) = dx (1 + (xa + xb) / (sa + sb)), and xa + sa = 1 / (sa - xa) for
// xa < 0. Branch-free (SelectLanes), so that loops over many VRLs vectorise.
template <typename Real>
[[gnu::always_inline]] inline Real AsinhDifferenceArgument(Real xa, Real dx, Real sa, Real sb) {
  Real xb = xa + dx, sum = xa + xb;
  bool mirror = sum < 0;
  Real near = SelectLanes(mirror, -xb, xa), s_near = SelectLanes(mirror, sb, sa);
  Real near_plus_s = SelectLanes(near >= 0, near + s_near, 1 / (s_near - near));
  return dx * (1 + std::abs(sum) / (sa + sb)) / near_plus_s;
}

// asinh(x) for x >= 0 is log1p of x + x^2 / (1 + s), s = sqrt(1 + x^2) (no cancellation).
template <typename Real>
[[gnu::always_inline]] inline Real AsinhArgument(Real x, Real s) {
  return x * (1 + x / (1 + s));
}

// asinh(xa + dx) - asinh(xa) for dx >= 0 (AsinhDifferenceArgument).
template <typename Real>
Real AsinhDifference(Real xa, Real dx) {
  Real xb = xa + dx;
  return Log1pLanes(AsinhDifferenceArgument(xa, dx, SqrtLanes(1 + xa * xa), SqrtLanes(1 + xb * xb)));
}

// The smallest positive distance we trust for a quantity computed from coordinates of
// magnitude `scale`: below it, the value is rounding noise. Never below sqrt(min<Real>),
// so that densities like 1 / h stay finite.
template <typename Real>
Real NoiseFloor(Real scale) {
  return 4 * std::numeric_limits<Real>::epsilon() * scale + std::sqrt(std::numeric_limits<Real>::min());
}

// Whether an interval of this length has a representable density: differences inside it
// must be normal numbers (shorter ones are numerically a point).
template <typename Real>
bool RepresentableLength(Real length) {
  return length * std::numeric_limits<Real>::epsilon() >= std::numeric_limits<Real>::min();
}

}  // namespace vrlis
