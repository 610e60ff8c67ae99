#pragma once
// The seed's solution 1: p(theta) proportional to C1(theta) + C2(theta), normalised jointly.
//
// The CDF is a sum of two arctangents, i.e. the argument of z1(delta) z2(delta) with
// z_k = (alpha_k + beta_k delta) + i delta. Setting that argument to S = u (mass1 + mass2)
// gives Im(z1 z2 e^{-iS}) = 0, a quadratic in delta. Of its two roots the wanted one is
// where the argument crosses S increasing, i.e. where the quadratic's slope is +sqrt(disc).
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
  Real SampleQuadratic(Real s) const {
    const TruncatedCauchy<Real>&c1 = fit_.lobe[0], &c2 = fit_.lobe[1];
    Real sn = std::sin(s), cs = std::cos(s);
    Real a = (c1.beta() + c2.beta()) * cs - (c1.beta() * c2.beta() - 1) * sn;
    Real b = (c1.alpha() + c2.alpha()) * cs - (c1.alpha() * c2.beta() + c2.alpha() * c1.beta()) * sn;
    Real c = -c1.alpha() * c2.alpha() * sn;
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
