#pragma once
// The Henyey-Greenstein phase function: evaluate, sample, invert.
//
// Convention: cos is the cosine between the direction light travels before and after the
// scattering event, so g > 0 scatters forward. Values are densities over the sphere
// (they integrate to one over solid angle).
#include "math.hpp"

namespace vrlis {

// d = 1 + g^2 - 2 g cos, written in terms of 1 - cos and 1 + cos so that it does not cancel
// near either peak when |g| -> 1 (docs/maths.md#numerics). The phase function is
// (1 - g)(1 + g) / (4 pi d^(3/2)). kLanes: branch-free, d^(-3/2) by RsqrtLanes, for loops
// over lanes that compilers vectorise (lane_math.hpp).
template <bool kLanes = false, typename Real>
Real HenyeyGreensteinBase(Real g, Real one_minus_cos, Real one_plus_cos) {
  if constexpr (kLanes) {
    return SelectLanes(g >= 0, Sqr(1 - g) + 2 * g * one_minus_cos, Sqr(1 + g) - 2 * g * one_plus_cos);
  } else {
    return g >= 0 ? Sqr(1 - g) + 2 * g * one_minus_cos : Sqr(1 + g) - 2 * g * one_plus_cos;
  }
}

// Henyey-Greenstein's value as numerator over denominator, for a caller that needs both it and
// its reciprocal (one division each, side by side).
template <typename Real>
struct PhaseFraction {
  Real num, den;
};
template <typename Real>
PhaseFraction<Real> HenyeyGreensteinFraction(Real g, Real one_minus_cos, Real one_plus_cos) {
  Real denom = HenyeyGreensteinBase(g, one_minus_cos, one_plus_cos);
  return {(1 - g) * (1 + g), 4 * kPi<Real> * denom * std::sqrt(denom)};
}

template <bool kLanes = false, typename Real>
Real HenyeyGreenstein(Real g, Real one_minus_cos, Real one_plus_cos) {
  if constexpr (kLanes) {
    Real r = RsqrtLanes(HenyeyGreensteinBase<kLanes>(g, one_minus_cos, one_plus_cos));
    return (1 - g) * (1 + g) * (kInvPi<Real> / 4) * r * r * r;
  } else {
    PhaseFraction<Real> f = HenyeyGreensteinFraction(g, one_minus_cos, one_plus_cos);
    return f.num / f.den;
  }
}

template <bool kLanes = false, typename Real>
Real HenyeyGreenstein(Real g, Real cos) {
  return HenyeyGreenstein<kLanes>(g, 1 - cos, 1 + cos);
}

// The value at the lobe's peak (cos = 1 for g >= 0, cos = -1 for g < 0).
template <typename Real>
Real HenyeyGreensteinPeak(Real g) {
  Real a = std::abs(g);
  return (1 + a) / (4 * kPi<Real> * Sqr(1 - a));
}

// Returns 1 - cos for the cos whose cumulative probability P(cos' <= cos) is u; precise
// near cos = 1.
template <typename Real>
Real SampleHenyeyGreensteinOneMinusCos(Real g, Real u) {
  Real v = 1 - u;  // v = P(cos' >= cos)
  Real q = 1 + g - 2 * g * v;
  Real s = (1 - g) * (1 + g) / q;
  return Clamp(v * (1 - g) * (s + 1 - g) / q, Real(0), Real(2));
}

// Samples cos with density HenyeyGreenstein(g, cos) * 2 pi.
template <typename Real>
Real SampleHenyeyGreenstein(Real g, Real u) { return 1 - SampleHenyeyGreensteinOneMinusCos(g, u); }

}  // namespace vrlis
