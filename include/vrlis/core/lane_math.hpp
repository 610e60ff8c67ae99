#pragma once
// sin, cos and 1/sqrt for loops over many values (a fit's nodes), in a form compilers
// vectorise: a call to libm cannot be, and neither can std::sqrt unless errno is off
// (-fno-math-errno, which a header cannot impose). So in float these are inlined,
// branch-free arithmetic; double keeps the standard functions. Outside such loops use the
// standard functions (SinCos below: for one value, glibc's sincosf is the fastest scalar version we
// measured; two independent values, as Novak's fit's two rotations, are cheaper inline).
//
// SinCosLanes: x = k pi/2 + r with k the nearest integer to x 2/pi (pi/2 split into three floats, the
// first with 8 significant bits, so that k times it is exact for |k| < 2^16), then the
// Taylor series of sin r to r^9 and of cos r to r^10 on |r| <= pi/4. Their truncation
// errors are below the next terms, (pi/4)^11 / 11! = 1.8e-9 and (pi/4)^12 / 12! = 1.2e-10,
// far below float's half ulp, so the error is rounding only: within 2 ulp of 1 in absolute
// terms and relative for sin near 0 (tests/lib/sincos.cpp checks both against double over
// |x| <= 100). Valid for |x| < 4e6 (the rounding trick below), accurate for |x| <= 1e4;
// every caller passes angles of a few pi.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace vrlis {

template <typename Real>
struct SinCosPair {
  Real sin, cos;
};

template <typename Real>
SinCosPair<Real> SinCos(Real x) { return {std::sin(x), std::cos(x)}; }

template <typename Real>
[[gnu::always_inline]] inline SinCosPair<Real> SinCosLanes(Real x) {
  if constexpr (!std::is_same_v<Real, float>) {
    return {std::sin(x), std::cos(x)};
  } else {
    // Adding 1.5 * 2^23 rounds to the nearest integer and leaves it in the low mantissa
    // bits (no float-to-int conversion, so NaN stays defined behaviour and propagates).
    constexpr float kShift = 12582912.0f;
    float shifted = x * 0.63661977236758134f + kShift;
    float k = shifted - kShift;
    std::uint32_t bits;
    std::memcpy(&bits, &shifted, sizeof bits);
    float r = ((x - k * 1.5703125f) - k * 4.837512969970703125e-4f) - k * 7.54978995489188216e-8f;
    float z = r * r;
    float s = r + r * z * (-1.6666667e-1f + z * (8.3333333e-3f + z * (-1.9841270e-4f + z * 2.7557319e-6f)));
    float c = 1 - 0.5f * z + z * z * (4.1666667e-2f + z * (-1.3888889e-3f + z * (2.4801587e-5f + z * -2.7557319e-7f)));
    // Quadrant k mod 4: (s, c), (c, -s), (-s, -c), (-c, s), chosen with bit masks: the
    // quadrant is random across calls, and branches on it would be mispredicted.
    std::uint32_t sb, cb;
    std::memcpy(&sb, &s, sizeof sb);
    std::memcpy(&cb, &c, sizeof cb);
    std::uint32_t swap = 0u - (bits & 1u);
    std::uint32_t sin_bits = ((sb & ~swap) | (cb & swap)) ^ ((bits & 2u) << 30);
    std::uint32_t cos_bits = ((cb & ~swap) | (sb & swap)) ^ (((bits + 1u) & 2u) << 30);
    SinCosPair<float> out;
    std::memcpy(&out.sin, &sin_bits, sizeof sin_bits);
    std::memcpy(&out.cos, &cos_bits, sizeof cos_bits);
    return out;
  }
}

// 1 / sqrt(x) for normal x > 0: the classic bit-level first guess (relative error below
// 3.5e-3), then three Newton steps, each squaring the relative error (to 3.6e-5, 2e-9,
// below rounding): within 2 ulp (tests/lib/lane_math.cpp).
template <typename Real>
[[gnu::always_inline]] inline Real RsqrtLanes(Real x) {
  if constexpr (!std::is_same_v<Real, float>) {
    return 1 / std::sqrt(x);
  } else {
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    bits = 0x5f375a86u - (bits >> 1);
    float y;
    std::memcpy(&y, &bits, sizeof y);
    float half = 0.5f * x;
    for (int i = 0; i < 3; ++i) y = y * (1.5f - half * y * y);
    return y;
  }
}

}  // namespace vrlis

namespace vrlis {

// m ? yes : no for floats, as bit masks: compilers keep it branch-free.
[[gnu::always_inline]] inline float LaneSelect(bool m, float yes, float no) {
  std::uint32_t y, n, mask = 0u - std::uint32_t(m);
  std::memcpy(&y, &yes, sizeof y);
  std::memcpy(&n, &no, sizeof n);
  std::uint32_t r = (y & mask) | (n & ~mask);
  float out;
  std::memcpy(&out, &r, sizeof out);
  return out;
}

// Atan2 (core/math.hpp) without branches, for inline use where its octant is random across
// calls (the Cauchy fits' arctangents, whose branches in Atan2 were mispredicted about half
// the time) and for loops compilers vectorise. The same polynomial (tools/fit_atan.py) in
// Estrin's form (half the chain of dependent operations of Horner's), and the same
// reflections as bit selections: relative error within 3 ulp of float, NaN in, NaN out
// (tests/lib/lane_math.cpp). double uses std::atan2.
template <typename Real>
[[gnu::always_inline]] inline Real Atan2Lanes(Real y, Real x) {
  if constexpr (!std::is_same_v<Real, float>) {
    return std::atan2(y, x);
  } else {
    float ax = std::abs(x), ay = std::abs(y);
    bool steep = ax < ay;
    float hi = steep ? ay : ax, lo = steep ? ax : ay;  // maxss, minss
    // Dividing by at least the smallest subnormal turns atan2(0, 0) into 0, not 0 / 0.
    constexpr float kTiny = 0x1p-149f;
    float t = lo / (hi < kTiny ? kTiny : hi), s = t * t, s2 = s * s, s4 = s2 * s2;
    float p = ((0.99999998f - 0.33333073f * s) + (0.19992619f - 0.14203643f * s) * s2) +
              s4 * (((0.10640930f - 0.075042865f * s) + (0.042691423f - 0.016068569f * s) * s2) + 0.0028498742f * s4);
    float a = t * p;
    // Steep: pi/2 - a; then x < 0: pi - a; then the sign of y. Masks, not branches.
    a = LaneSelect(steep, 1.5707963f - a, a);
    a = LaneSelect(x < 0, 3.1415927f - a, a);
    return std::copysign(a, y);
  }
}

}  // namespace vrlis
