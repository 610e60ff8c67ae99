#pragma once
// Small numeric helpers shared by every sampler.
#include <algorithm>
#include <cmath>
#include <limits>

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

// sin^2(x / 2): the half-angle form keeps 1 - cos(x) exact near x = 0.
template <typename Real>
Real SinSqrHalf(Real x) { return Sqr(std::sin(x / 2)); }

// asinh(xa + dx) - asinh(xa) for dx >= 0, without the cancellation of the naive difference
// when both arguments are large and of one sign.
template <typename Real>
Real AsinhDifference(Real xa, Real dx) {
  Real xb = xa + dx;
  if (xa + xb < 0) {  // mirror so that the larger magnitude is positive
    Real t = -xb;
    xb = -xa;
    xa = t;
  }
  Real sa = std::sqrt(1 + xa * xa), sb = std::sqrt(1 + xb * xb);
  Real xa_plus_sa = xa >= 0 ? xa + sa : 1 / (sa - xa);
  return std::log1p(dx * (1 + (xa + xb) / (sa + sb)) / xa_plus_sa);
}

// The smallest positive distance we trust for a quantity computed from coordinates of
// magnitude `scale`: below it, the value is rounding noise.
template <typename Real>
Real NoiseFloor(Real scale) {
  return 4 * std::numeric_limits<Real>::epsilon() * scale + std::numeric_limits<Real>::min();
}

}  // namespace vrlis
