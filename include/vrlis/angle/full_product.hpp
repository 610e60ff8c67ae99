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
#include <array>
#include <limits>

#include "phase_product.hpp"

namespace vrlis {

template <typename Real>
class FullProductTarget {
 public:
  // Floor for piecewise-linear fits of this target: transmittance underflows to exactly 0
  // on long segments, and a density must stay positive wherever the integrand is.
  static constexpr Real kRelativeFloor = Real(1e-3);

  FullProductTarget(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom)
      : phase_(q, dom), sigma_h_(q.sigma_t * dom.h()), width_(dom.width()) {}

  Real operator()(Real delta) const {
    Real half = phase_.segment_half_angle(delta), sin_half = std::sin(half), cos_half = std::cos(half);
    Real value = phase_.segment_lobe(sin_half, cos_half) * phase_.point_lobe(delta);
    if (sigma_h_ > 0) {
      Real cos_half_a = std::cos(phase_.segment_half_angle(0));
      value *= std::exp(-sigma_h_ * std::sin(delta / 2) / (cos_half_a * std::max(cos_half, Real(0))));
    }
    return value;
  }
  // The value at every offset in `delta` (a fit's nodes): the phase product's branch-free
  // loop, then the transmittance in another, with cos(x/2) = cos(delta/2 - lower/2) by the
  // subtraction formula from one sincos of delta / 2 per node (whose sine the optical depth
  // needs too). Both loops vectorise in float.
  template <std::size_t N>
  void evaluate(const std::array<Real, N>& delta, std::array<Real, N>& out) const {
    phase_.evaluate(delta, out);
    if (!(sigma_h_ > 0)) return;
    // pole.cos = cos(x_a / 2): the optical depth's constant factor comes with it.
    const SinCosPair<Real> pole = SinCosLanes(phase_.lower_pole() / 2);
    const Real depth_scale = sigma_h_ / pole.cos;
    for (std::size_t j = 0; j < N; ++j) {
      SinCosPair<Real> half = SinCosLanes(delta[j] / 2);
      Real cos_half = half.cos * pole.cos + half.sin * pole.sin;
      out[j] *= ExpLanes(-depth_scale * half.sin / std::max(cos_half, Real(0)));
    }
  }

  bool point_lobe_flat() const { return phase_.point_lobe_flat(); }
  Real point_peak() const { return phase_.point_peak(); }
  const PhaseProduct<Real>& phase() const { return phase_; }

  // The fit's split points: the point lobe's peak (as Novák's), and where the segment lobe x
  // transmittance peaks inside the interval. For g < 0 the segment lobe grows towards the
  // far pole while the transmittance falls, so their product peaks inside; a fit that
  // misses that peak puts a tiny density under most of the integral (docs/maths.md#full-product).
  int splits(std::array<Real, 2>& out) const {
    int n = phase_.splits(out);
    Real peak = SegmentTransmittancePeak();
    if (peak > 0 && peak < width_) {
      if (n == 1 && std::abs(peak - out[0]) <= width_ * Real(1e-3)) return n;  // one node serves both
      out[n++] = peak;
      if (n == 2 && out[1] < out[0]) std::swap(out[0], out[1]);
    }
    return n;
  }

  // With y = x/2 the segment lobe's half scattering angle and c = cos y, the log-derivative
  // of lobe x transmittance in x vanishes where 12 |g| sin(y) c^3 = sigma_t h D(c), D the
  // lobe's denominator (1 + g)^2 + 4 |g| c^2 (g < 0). Divided by c^4 and written in
  // t = tan y (w = 1 + t^2 = 1 / c^2) it is the root of a quartic with no square roots,
  //   P(t) = sigma_t h ((1 + g)^2 w^2 + 4 |g| w) - 12 |g| t,
  // negative where the product rises along x. P is convex, so its maximum is P's larger
  // root, and Newton from the right of it descends to it monotonically. A start there: where
  // the quartic term alone, or the quadratic one alone, outweighs 12 |g| t, i.e. the smaller
  // of t^3 = 12 |g| / (sigma_t h (1 + g)^2) and t = 3 / (sigma_t h); at either P > 0 and
  // P' >= 12 |g| > 0. Returns the peak's offset, or -1 when the product has no interior
  // peak (P positive throughout: the iteration meets P' <= 0 or stalls).
  Real SegmentTransmittancePeak() const {
    Real g = phase_.segment_g();
    if (!(g < 0) || !(sigma_h_ > 0)) return -1;
    Real a = -g, k = 12 * a, quartic = sigma_h_ * Sqr(1 + g), quadratic = 4 * a * sigma_h_;
    Real t = std::min(std::cbrt(k / quartic), 3 / sigma_h_);
    if (!std::isfinite(t)) return -1;
    Real p = 0;
    for (int i = 0; i < 8; ++i) {
      Real w = 1 + t * t;
      p = (quartic * w + quadratic) * w - k * t;
      Real dp = (4 * quartic * w + 2 * quadratic) * t - k;
      if (!(dp > 0)) return -1;  // left of P's minimum: no root to its right
      Real step = p / dp;
      t -= step;
      if (step <= Real(1e-4) * t) break;  // the next step would be below float rounding
    }
    if (!(t > 0) || !(p <= Real(1e-3) * quartic * Sqr(1 + t * t))) return -1;
    return 2 * Atan2Lanes(t, Real(1)) + phase_.lower_pole();
  }

 private:
  PhaseProduct<Real> phase_;
  Real sigma_h_, width_;
};

}  // namespace vrlis
