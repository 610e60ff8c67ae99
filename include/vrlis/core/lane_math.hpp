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
// terms and relative for sin near 0 (tests/lib/lane_math.cpp checks both against double over
// |x| <= 100). Valid for |x| < 4e6 (the rounding trick below), accurate for |x| <= 1e4;
// every caller passes angles of a few pi.
//
// Log1pLanes and Expm1Lanes serve the hot path's hyperbolic functions (the VRL point of
// step one), where glibc's log1pf and expm1f took a quarter of a gather; see each below.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace vrlis {

template <typename Real>
struct SinCosPair {
  Real sin, cos;
};

// How many digits SinCosLanes, RsqrtLanes and ExpLanes keep in float. Full: within a few ulp
// (samples, densities, inverses). Fit: within 1e-4 relative (tests/lib/lane_math.cpp), for
// the values a fit is built from (a piecewise-linear density's node values): the density is
// exact whatever they are, since its pdf comes from the same stored values, and an error of
// 1e-4 in them moves the variance far less than the fit's own approximation does. Fewer
// terms, fewer cycles (what the fits gain: docs/maths.md#vrl-marginal).
enum class Accuracy { Full, Fit };

template <typename Real>
SinCosPair<Real> SinCos(Real x) { return {std::sin(x), std::cos(x)}; }

// (sin, cos) of k pi/2 + r from those of r (s, c) and k's low bits (in `quadrant`): (s, c),
// (c, -s), (-s, -c), (-c, s) for k mod 4 = 0 to 3, chosen with bit masks: the quadrant is random
// across calls, and branches on it would be mispredicted.
template <typename Real, typename Bits>
[[gnu::always_inline]] inline SinCosPair<Real> Quadrant(Real s, Real c, Bits quadrant) {
  static_assert(sizeof(Real) == sizeof(Bits), "the masks are the floating-point values' width");
  constexpr Bits kShift = 8 * sizeof(Bits) - 2;  // bit 1 of the quadrant to the sign bit
  Bits sb, cb;
  std::memcpy(&sb, &s, sizeof sb);
  std::memcpy(&cb, &c, sizeof cb);
  const Bits swap = Bits(0) - (quadrant & 1u);
  const Bits sin_bits = ((sb & ~swap) | (cb & swap)) ^ ((quadrant & 2u) << kShift);
  const Bits cos_bits = ((cb & ~swap) | (sb & swap)) ^ (((quadrant + 1u) & 2u) << kShift);
  SinCosPair<Real> out;
  std::memcpy(&out.sin, &sin_bits, sizeof sin_bits);
  std::memcpy(&out.cos, &cos_bits, sizeof cos_bits);
  return out;
}

template <Accuracy kAccuracy = Accuracy::Full, typename Real>
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
    // Fit: to r^5 and r^6, truncated below (pi/4)^7 / 7! = 3.7e-5 and (pi/4)^8 / 8! = 3.6e-6.
    float s = r + r * z *
                      (kAccuracy == Accuracy::Fit
                           ? -1.6666667e-1f + z * 8.3333333e-3f
                           : -1.6666667e-1f + z * (8.3333333e-3f + z * (-1.9841270e-4f + z * 2.7557319e-6f)));
    float c = 1 - 0.5f * z +
              z * z *
                  (kAccuracy == Accuracy::Fit
                       ? 4.1666667e-2f + z * -1.3888889e-3f
                       : 4.1666667e-2f + z * (-1.3888889e-3f + z * (2.4801587e-5f + z * -2.7557319e-7f)));
    return Quadrant(s, c, bits);
  }
}

// sin and cos of a float computed in double and rounded to float, branch-free for loops: the
// reduction of SinCosLanes with pi/2 in three doubles (the first two of 32 significant bits, so
// that k times them is exact for |k| < 2^21), then the Taylor series of sin r to r^13 and of
// cos r to r^14, truncated below (pi/4)^15 / 15! = 2.1e-14 and (pi/4)^16 / 16! = 1.0e-15. Each
// is then the float nearest the true value unless that lies within about 2e-14 of halfway
// between two floats, so it follows x monotonically wherever sin or cos does, as glibc's
// sincosf (also computed in double and rounded) does: what a sampler that must keep its
// samples' order can take in vector lanes (samplers/cauchy_lobe.hpp). For |x| <= 1e4.
[[gnu::always_inline]] inline SinCosPair<float> SinCosRounded(float x) {
  const double d = x;
  constexpr double kShift = 0x1.8p52;  // adding it rounds to an integer, left in the low bits
  const double shifted = d * 0.6366197723675814 + kShift;
  const double k = shifted - kShift;
  std::uint64_t bits;
  std::memcpy(&bits, &shifted, sizeof bits);
  const double r = ((d - k * 0x1.921fb544p+0) - k * 0x1.0b4611a6p-34) - k * 0x1.3198a2e037073p-69;
  const double z = r * r;
  const double s =
      r + r * z *
              (-0.16666666666666666 +
               z * (0.008333333333333333 +
                    z * (-0.0001984126984126984 +
                         z * (2.7557319223985893e-06 + z * (-2.505210838544172e-08 + z * 1.6059043836821613e-10)))));
  const double c =
      1 - 0.5 * z +
      z * z *
          (0.041666666666666664 +
           z * (-0.001388888888888889 +
                z * (2.48015873015873e-05 + z * (-2.755731922398589e-07 + z * (2.08767569878681e-09 +
                                                                                  z * -1.1470745597729725e-11)))));
  const SinCosPair<double> e = Quadrant(s, c, bits);
  return {static_cast<float>(e.sin), static_cast<float>(e.cos)};
}

// 1 / sqrt(x) for normal x > 0: the classic bit-level first guess (relative error below
// 3.5e-2), then three Newton steps, each taking the error e to about 1.5 e^2 (measured
// 1.8e-3, 4.7e-6, then rounding only): within 2 ulp (tests/lib/lane_math.cpp); two steps
// (Accuracy::Fit) leave 40 ulp.
template <Accuracy kAccuracy = Accuracy::Full, typename Real>
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
    for (int i = 0; i < (kAccuracy == Accuracy::Fit ? 2 : 3); ++i) y = y * (1.5f - half * y * y);
    return y;
  }
}

// c ? a : b, with a and b both computed. A compiler that keeps floating-point exceptions
// (GCC's default -ftrapping-math) will not compute an operand a branch skipped, so a
// ternary between two computations keeps the loop scalar; this select is bit arithmetic
// on values already computed, which vectorises.
template <typename Real>
[[gnu::always_inline]] inline Real SelectLanes(bool c, Real a, Real b) {
  if constexpr (std::is_same_v<Real, float> || std::is_same_v<Real, double>) {
    using Bits = std::conditional_t<std::is_same_v<Real, float>, std::uint32_t, std::uint64_t>;
    Bits mask = Bits(0) - static_cast<Bits>(c), ab, bb;
    std::memcpy(&ab, &a, sizeof ab);
    std::memcpy(&bb, &b, sizeof bb);
    const Bits bits = (ab & mask) | (bb & ~mask);
    Real out;
    std::memcpy(&out, &bits, sizeof out);
    return out;
  } else {
    return c ? a : b;
  }
}

// sqrt(x) for x = 0, normal x > 0 and +inf (tests/lib/lane_math.cpp): std::sqrt sets errno
// for negative x unless -fno-math-errno, and that call keeps a loop scalar. float:
// x RsqrtLanes(x), within 3 ulp. double (the float samplers' widened arithmetic): the
// bit-level first guess of 1 / sqrt(x) (relative error below 3.5e-2), four Newton steps
// (to about 1e-10), then one Newton step on the root itself: within 1 ulp.
template <typename Real>
[[gnu::always_inline]] inline Real SqrtLanes(Real x) {
  constexpr Real kInf = std::numeric_limits<Real>::infinity();
  if constexpr (std::is_same_v<Real, float>) {
    return SelectLanes(x < kInf, x * RsqrtLanes(x), x);
  } else if constexpr (std::is_same_v<Real, double>) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    bits = 0x5fe6eb50c7b537a9ull - (bits >> 1);
    double y;
    std::memcpy(&y, &bits, sizeof y);
    const double half = 0.5 * x;
    for (int i = 0; i < 4; ++i) y = y * (1.5 - half * y * y);
    const double root = x * y;
    return SelectLanes(x < kInf, root + (half - 0.5 * root * root) * y, x);
  } else {
    return std::sqrt(x);
  }
}

// x^(1/3) for normal x > 0 (a starting guess for Newton's method, not a libm replacement):
// the bit-level first guess of x^(-1/3) (relative error below 3.5e-2), two Newton steps
// r (4 - x r^3) / 3, which need no division and take the error to 1.2e-5, then x r^2: within
// 2.5e-5 relative (tests/lib/lane_math.cpp). glibc's cbrtf, which calls frexpf and scalbnf,
// was 4% of FullProduct's camera step at g < 0. double uses std::cbrt.
template <typename Real>
[[gnu::always_inline]] inline Real CbrtLanes(Real x) {
  if constexpr (!std::is_same_v<Real, float>) {
    return std::cbrt(x);
  } else {
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    bits = 0x54a22900u - bits / 3;
    float r;
    std::memcpy(&r, &bits, sizeof r);
    float third = x * (1.0f / 3);
    for (int i = 0; i < 2; ++i) r = r * (4.0f / 3 - third * r * r * r);
    return x * r * r;
  }
}

namespace detail {
inline float FloatFromBits(std::uint32_t bits) {
  float x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}
inline std::uint32_t BitsOfFloat(float x) {
  std::uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}
// x = k ln 2 + r with k the nearest integer to x / ln 2 (the rounding trick of SinCosLanes:
// adding 1.5 * 2^23 leaves k in the low mantissa bits) and |r| <= ln(2) / 2; ln 2 is split in
// two floats, the first with 16 significant bits, so that k times it is exact for |k| < 256.
constexpr float kLn2Hi = 0.693145751953125f, kLn2Lo = 1.42860682030941723212e-6f;
struct Ln2Reduction {
  float kf;        // k as a float
  std::int32_t k;  // k as an integer
  float r;
};
[[gnu::always_inline]] inline Ln2Reduction ReduceLn2(float x) {
  constexpr float kShift = 12582912.0f;
  float shifted = x * 1.44269504f + kShift;
  float kf = shifted - kShift;
  return {kf, static_cast<std::int32_t>(BitsOfFloat(shifted) - BitsOfFloat(kShift)), (x - kf * kLn2Hi) - kf * kLn2Lo};
}
// 2^k for k in [-126, 127], put into the exponent bits.
[[gnu::always_inline]] inline float TwoToThe(std::int32_t k) { return FloatFromBits(static_cast<std::uint32_t>(k + 127) << 23); }
}  // namespace detail

// log(1 + x) for x >= -1 (-1 gives -inf, below it NaN, +inf and NaN pass through).
// u = 1 + x is rounded; its rounding error c = (1 + x) - u is exact (Fast2Sum) and adds
// c / u. u = 2^k m with m in [sqrt(1/2), sqrt(2)), f = m - 1 exact, s = f / (2 + f) and
// log m = 2 atanh s = f - f^2/2 + s (f^2/2 + R), R = 2 s^2/3 + 2 s^4/5 + ... (Taylor; |s| < 0.172,
// so the terms after s^8 are below 1e-9 of the result): the large term f is exact and the
// rest a small correction, within 1 ulp (tests/lib/lane_math.cpp).
template <typename Real>
[[gnu::always_inline]] inline Real Log1pLanes(Real x) {
  if constexpr (!std::is_same_v<Real, float>) {
    return std::log1p(x);
  } else {
    float u = 1 + x;
    float c = SelectLanes(x > 1, 1 - (u - x), x - (u - 1)) / u;
    std::uint32_t bits = detail::BitsOfFloat(u);
    // The exponent of u relative to sqrt(1/2)'s, as an arithmetic shift of a signed difference.
    std::int32_t k = static_cast<std::int32_t>(bits - 0x3f3504f3u) >> 23;
    float f = detail::FloatFromBits(bits - (static_cast<std::uint32_t>(k) << 23)) - 1;
    float s = f / (2 + f), z = s * s;
    float r = z * (0.66666667f + z * (0.4f + z * (0.28571429f + z * 0.22222222f)));
    float half_f2 = 0.5f * f * f, kf = static_cast<float>(k);
    float log = kf * detail::kLn2Hi + (f - (half_f2 - (s * (half_f2 + r) + (kf * detail::kLn2Lo + c))));
    // Outside (0, inf) u is -1's image (-inf), below it (NaN), +inf or NaN.
    constexpr float kInf = std::numeric_limits<float>::infinity();
    float special = SelectLanes(u == 0, -kInf, SelectLanes(u > 0, u, std::numeric_limits<float>::quiet_NaN()));
    return SelectLanes((u > 0) & (u < kInf), log, special);
  }
}

// exp(x) - 1. x = k ln 2 + r with |r| <= ln(2)/2 (detail::ReduceLn2), expm1(r) by its Taylor series to r^8 (the
// rest is below 6e-10 of it), then 2^k (1 + p) - 1 = 2^k p + (2^k - 1), whose second term is
// exact for k <= 24; above, 2^(k - 1) (1 + p) 2 - 1, which overflows to +inf past float's range
// as it should. x is clamped to [-20, 88.8] first (expm1 is -1 in float below -17.4 and
// overflows above 88.73), which keeps 2^k normal. NaN passes through. Within 2 ulp
// (tests/lib/lane_math.cpp), relative for tiny x.
template <typename Real>
[[gnu::always_inline]] inline Real Expm1Lanes(Real x) {
  if constexpr (!std::is_same_v<Real, float>) {
    return std::expm1(x);
  } else {
    float xc = SelectLanes(x < -20.0f, -20.0f, SelectLanes(x > 88.8f, 88.8f, x));
    detail::Ln2Reduction red = detail::ReduceLn2(xc);
    float r = red.r;
    float p = r + r * r * (0.5f + r * (1.6666667e-1f + r * (4.1666667e-2f + r * (8.3333333e-3f +
                                      r * (1.3888889e-3f + r * (1.9841270e-4f + r * 2.4801587e-5f))))));
    float scale = detail::TwoToThe(red.k), half_scale = detail::TwoToThe(red.k - 1);
    return SelectLanes(red.kf <= 24, scale * p + (scale - 1), half_scale * (1 + p) * 2 - 1);
  }
}

// exp(x) for x <= 88, vectorisable in float: x = k ln 2 + r (detail::ReduceLn2), the Taylor
// series of exp r to r^7 on |r| <= ln(2) / 2 (truncation below (ln(2)/2)^8 / 8! = 5e-9, under float's half
// ulp; Accuracy::Fit: to r^4, below (ln(2)/2)^5 / 5! = 4.2e-5), then 2^k put into the exponent
// bits. Within 2 ulp of exp (tests/lib/lane_math.cpp) down to the smallest normal float;
// below it (x < -87.3, subnormal results) 0, and exp(-inf) = 0. NaN propagates.
template <Accuracy kAccuracy = Accuracy::Full, typename Real>
[[gnu::always_inline]] inline Real ExpLanes(Real x) {
  if constexpr (!std::is_same_v<Real, float>) {
    return std::exp(x);
  } else {
    constexpr float kSmallest = -87.33654f;  // ln of the smallest normal float
    detail::Ln2Reduction red = detail::ReduceLn2(x);
    float r = red.r;
    float p = 1 + r * (1 + r * (0.5f + r * (kAccuracy == Accuracy::Fit
                                                ? 1.6666667e-1f + r * 4.1666667e-2f
                                                : 1.6666667e-1f + r * (4.1666667e-2f + r * (8.3333333e-3f + r * (1.3888889e-3f + r * 1.9841270e-4f))))));
    // Below kSmallest 2^k is no normal float: 0, by a select (SelectLanes, so that loops vectorise).
    return SelectLanes(x < kSmallest, 0.0f, p * detail::TwoToThe(red.k));
  }
}


// atan2 for the samplers' hot paths. glibc's atan2f costs several times its sinf, and the
// Cauchy samplers are made of arctangents, so float gets a polynomial: atan(t) = t P(t^2)
// on [0, 1], P fitted for minimal maximum relative error (1.6e-8, below float's half ulp;
// the fit is reproduced by tools/fit_atan.py), in Estrin's form (half the chain of
// dependent operations of Horner's), with the reflections to the other octants as bit
// selections: no branches, which were mispredicted about half the time (the octant is
// random across calls), and loops over it vectorise. Relative error within 3 ulp of float,
// kept for small results, which matter most (offsets next to an endpoint); NaN in, NaN out
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
    // Steep: pi/2 - a; then x < 0: pi - a; then the sign of y. Masks, not branches, and on
    // constants only: each reflection is o + s a with (o, s) = (pi/2 or pi, -1) or (0, 1),
    // the same roundings as pi/2 - a and pi - a, while the masks are computed beside the
    // polynomial (selecting on a itself put their transfers after it).
    float steep_o = SelectLanes(steep, 1.5707963f, 0.0f), steep_s = SelectLanes(steep, -1.0f, 1.0f);
    float back_o = SelectLanes(x < 0, 3.1415927f, 0.0f), back_s = SelectLanes(x < 0, -1.0f, 1.0f);
    float a = back_o + back_s * (steep_o + steep_s * (t * p));
    return std::copysign(a, y);
  }
}

// c ? a : b. kLanes: by bit masks, both computed (SelectLanes), for loops that vectorise
// (SampleVrlPoints, MediumGatherBounds); else a plain choice, which lets one query at a time skip
// the other case.
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline Real Pick(bool c, Real a, Real b) {
  if constexpr (kLanes) {
    return SelectLanes(c, a, b);
  } else {
    return c ? a : b;
  }
}

// sqrt(x): by the vectorisable SqrtLanes in the lanes' arithmetic, else by the square-root
// instruction (half the latency of SqrtLanes' Newton steps; VrlPoint one VRL at a time ran
// 1.18x slower with SqrtLanes). The two round differently, within 3 ulp.
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline Real PickSqrt(Real x) {
  if constexpr (kLanes) {
    return SqrtLanes(x);
  } else {
    return std::sqrt(x);
  }
}

// exp(x): by ExpLanes in the lanes' arithmetic, else by libm (glibc picks an FMA build of
// expf at run time, faster for one value than ExpLanes compiled for the baseline instruction set).
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline Real PickExp(Real x) {
  if constexpr (kLanes) {
    return ExpLanes(x);
  } else {
    return std::exp(x);
  }
}

// 1 / sqrt(x), as PickSqrt.
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline Real PickRsqrt(Real x) {
  if constexpr (kLanes) {
    return RsqrtLanes(x);
  } else {
    return 1 / std::sqrt(x);
  }
}

}  // namespace vrlis
