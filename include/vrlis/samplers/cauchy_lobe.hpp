#pragma once
// A Cauchy density in the angle domain, truncated to [0, width], and the seed's fit of one
// to each phase lobe. Shared by the Cauchy sum and the Cauchy mixture.
//
// With x = (theta - mu) / gamma, the primitive atan(x) - atan(x_a) is the argument of
// (1 + i x)(1 - i x_a), i.e. of z(delta) = (alpha + beta delta) + i delta once scaled by
// gamma. Working with z keeps the truncated mass exact for tiny gamma and peaks near an end.
#include <array>

#include "../angle/phase_product.hpp"

namespace vrlis {

template <typename Real>
class TruncatedCauchy {
 public:
  TruncatedCauchy() = default;
  // location: offset of the peak from theta_a (may lie outside the interval).
  TruncatedCauchy(Real location, Real scale, Real width)
      : location_(location),
        scale_(scale),
        alpha_(scale + location * location / scale),
        beta_(-location / scale),
        mass_(Atan2(width, alpha_ + beta_ * width)),
        width_(width) {}

  // gamma / ((delta - mu)^2 + gamma^2): pi times the Cauchy density; integrates to mass().
  Real density(Real delta) const { return scale_ / (Sqr(delta - location_) + Sqr(scale_)); }
  // Its integral over [0, delta].
  Real primitive(Real delta) const { return Atan2(delta, alpha_ + beta_ * delta); }
  // The delta whose primitive is s, for s in [0, mass()].
  Real inverse_primitive(Real s) const {
    Real sn = std::sin(s), denom = std::cos(s) - beta_ * sn;
    return denom > 0 ? Clamp(alpha_ * sn / denom, Real(0), width_) : width_;
  }
  Real mass() const { return mass_; }
  Real location() const { return location_; }
  Real alpha() const { return alpha_; }
  Real beta() const { return beta_; }

 private:
  Real location_ = 0, scale_ = 1, alpha_ = 1, beta_ = 0, mass_ = 0, width_ = 0;
};

// The seed's fit: a Cauchy located at the lobe's peak whose peak value 1 / (pi gamma)
// equals the lobe's peak value. Lobes constant in theta only scale the product and are
// left out (so that g = 0 reduces to equiangular sampling exactly).
template <typename Real>
struct CauchyLobes {
  std::array<TruncatedCauchy<Real>, 2> lobe;
  std::array<bool, 2> from_segment{};  // which phase lobe each Cauchy stands for
  int count = 0;

  explicit CauchyLobes(const PhaseProduct<Real>& target) {
    if (!target.segment_lobe_flat()) Add(target.segment_peak(), target.segment_peak_value(), target.width(), true);
    if (!target.point_lobe_flat()) Add(target.point_peak(), target.point_peak_value(), target.width(), false);
  }

 private:
  void Add(Real peak, Real peak_value, Real width, bool segment) {
    lobe[count] = TruncatedCauchy<Real>(peak, 1 / (kPi<Real> * peak_value), width);
    from_segment[count++] = segment;
  }
};

}  // namespace vrlis
