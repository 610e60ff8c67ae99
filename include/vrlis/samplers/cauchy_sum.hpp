#pragma once
// The seed's solution 1: p(theta) proportional to C1(theta) + C2(theta), normalised jointly.
//
// The CDF is a sum of two arctangents, i.e. the argument of z1(delta) z2(delta) (see
// cauchy_lobe.hpp). Setting that argument to S = u (mass1 + mass2)
// gives Im(z1 z2 e^{-iS}) = 0, a quadratic in delta. Of its two roots the wanted one is
// where the argument crosses S increasing, i.e. where the quadratic's slope is +sqrt(disc).
#include <algorithm>

#include "../angle/segment_sampler.hpp"
#include "cauchy_lobe.hpp"

namespace vrlis {

template <typename R>
class CauchySumAngle {
 public:
  using Real = R;
  CauchySumAngle(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom)
      : fit_(PhaseProduct<Real>(q, dom)), width_(dom.width()) {
    for (int k = 0; k < fit_.count; ++k) mass_ += fit_.lobe[k].mass();
  }

  Real sample(Real u) const {
    switch (fit_.count) {
      case 0: return u * width_;
      case 1: return fit_.lobe[0].inverse_primitive(u * mass_);
    }
    return SampleQuadratic(u * mass_);
  }

  Real pdf(Real delta) const {
    if (fit_.count == 0) return 1 / width_;
    Real sum = 0;
    for (int k = 0; k < fit_.count; ++k) sum += fit_.lobe[k].density(delta);
    return sum / mass_;
  }

  Real cdf(Real delta) const {
    if (fit_.count == 0) return delta / width_;
    Real sum = 0;
    for (int k = 0; k < fit_.count; ++k) sum += fit_.lobe[k].primitive(delta);
    return sum / mass_;
  }

 private:
  // With w_k = gamma_k z_k = (P_k - mu_k delta) + i gamma_k delta, P_k = gamma_k^2 + mu_k^2
  // (scaling by gamma_k > 0 keeps the argument), Im(w1 w2 e^{-iS}) = a delta^2 + b delta + c
  // has coefficients of order one even when gamma_k is tiny.
  Real SampleQuadratic(Real s) const {
    const TruncatedCauchy<Real>&c1 = fit_.lobe[0], &c2 = fit_.lobe[1];
    Real m1 = c1.location(), m2 = c2.location(), g1 = c1.scale(), g2 = c2.scale();
    Real p1 = g1 * c1.Re(0), p2 = g2 * c2.Re(0);
    Real sn = std::sin(s), cs = std::cos(s);
    Real a = -(g1 * m2 + g2 * m1) * cs - (m1 * m2 - g1 * g2) * sn;
    Real b = (g1 * p2 + g2 * p1) * cs + (p1 * m2 + p2 * m1) * sn;
    Real c = -p1 * p2 * sn;
    Real norm = std::max({std::abs(a), std::abs(b), std::abs(c)});  // keep b^2 - 4ac finite
    a /= norm;
    b /= norm;
    c /= norm;
    Real root = SafeSqrt(b * b - 4 * a * c);
    // (-b + root) / (2a), in whichever form does not cancel.
    Real delta = b > 0 ? -2 * c / (b + root) : (-b + root) / (2 * a);
    return delta >= 0 ? std::min(delta, width_) : Real(0);  // also maps NaN from a == 0 to 0
  }

  CauchyLobes<Real> fit_;
  Real width_;
  Real mass_ = 0;
};

template <typename Real = float>
using CauchySum = SegmentSampler<CauchySumAngle<Real>>;

}  // namespace vrlis
