#pragma once
// The whole angle-dependent part of a gather integrand: the phase product times the
// transmittance along the segment and from the segment point to p,
//   exp(-sigma_t ((t - tmin) + |x(t) - p|)),
// normalised to 1 at tmin (t + |x(t) - p| never decreases along the segment), so it cannot
// underflow where the integrand starts. The published samplers all leave transmittance
// out; in a dense medium or on a long camera segment it is the dominant factor.
//
// With x = theta + pi/2 the segment lobe's scattering angle, t + |x(t) - p| = u0 + h tan(x/2),
// so the optical depth from tmin is sigma_t h (tan(x/2) - tan(x_a/2))
//   = sigma_t h sin(delta/2) / (cos(x/2) cos(x_a/2)),
// which reuses the cosine the segment lobe needs anyway and never cancels.
#include "phase_product.hpp"

namespace vrlis {

template <typename Real>
class FullProductTarget {
 public:
  // Floor for piecewise-linear fits of this target: transmittance underflows to exactly 0
  // on long segments, and a density must stay positive wherever the integrand is.
  static constexpr Real kRelativeFloor = Real(1e-3);

  FullProductTarget(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom)
      : phase_(q, dom),
        depth_scale_(q.sigma_t * dom.h() / std::cos(phase_.segment_half_angle(0))) {}

  Real operator()(Real delta) const {
    Real half = phase_.segment_half_angle(delta), sin_half = std::sin(half), cos_half = std::cos(half);
    Real value = phase_.segment_lobe(sin_half, cos_half) * phase_.point_lobe(delta);
    if (depth_scale_ > 0) value *= std::exp(-depth_scale_ * std::sin(delta / 2) / std::max(cos_half, Real(0)));
    return value;
  }
  template <std::size_t N>
  void evaluate(const std::array<Real, N>& delta, std::array<Real, N>& out) const {
    for (std::size_t j = 0; j < N; ++j) out[j] = (*this)(delta[j]);
  }

  bool point_lobe_flat() const { return phase_.point_lobe_flat(); }
  Real point_peak() const { return phase_.point_peak(); }

 private:
  PhaseProduct<Real> phase_;
  Real depth_scale_;  // sigma_t h / cos(x_a / 2)
};

}  // namespace vrlis
