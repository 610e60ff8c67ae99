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
#include <cmath>
#include <cstdint>
#include <limits>

#include "phase_product.hpp"

namespace vrlis {

namespace detail {

// The transmittance factor at the offset whose half angle has sine and cosine `half`:
// pole = sin and cos of half the lower pole's offset, depth_scale = sigma_t h / pole.cos
// (see above). Branch-free, for loops over offsets.
template <Accuracy kAccuracy = Accuracy::Full, typename Real>
[[gnu::always_inline]] inline Real SegmentTransmittance(SinCosPair<Real> half, SinCosPair<Real> pole, Real depth_scale) {
  Real cos_half = half.cos * pole.cos + half.sin * pole.sin;  // cos(x/2) by the subtraction formula
  return ExpLanes<kAccuracy>(-depth_scale * half.sin / std::max(cos_half, Real(0)));
}

}  // namespace detail

template <typename Real>
class FullProductTarget {
 public:
  // Floor for piecewise-linear fits of this target: transmittance underflows to exactly 0
  // on long segments, and a density must stay positive wherever the integrand is.
  static constexpr Real kRelativeFloor = Real(1e-3);

  FullProductTarget(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom)
      : FullProductTarget(PhaseProduct<Real>(q, dom), q, dom) {}
  // With q's phase product built already (auto's rule builds it to choose).
  FullProductTarget(const PhaseProduct<Real>& phase, const SegmentQuery<Real>& q, const AngleDomain<Real>& dom)
      : phase_(phase),
        pole_(SinCosLanes(phase_.lower_pole() / 2)),  // pole_.cos = cos(x_a / 2)
        sigma_h_(q.sigma_t * dom.h()),
        depth_scale_(sigma_h_ / pole_.cos),
        width_(dom.width()) {}

  Real operator()(Real delta) const {
    Real half = phase_.segment_half_angle(delta), sin_half = std::sin(half), cos_half = std::cos(half);
    Real value = phase_.segment_lobe(sin_half, cos_half) * phase_.point_lobe(delta);
    if (depth_scale_ > 0) value *= std::exp(-depth_scale_ * std::sin(delta / 2) / std::max(cos_half, Real(0)));
    return value;
  }
  // The value at every offset in `delta` (a fit's nodes): the phase product's branch-free
  // loop, then the transmittance in another, with cos(x/2) = cos(delta/2 - lower/2) by the
  // subtraction formula from one sincos of delta / 2 per node (whose sine the optical depth
  // needs too). Both loops vectorise in float. kAccuracy as PhaseProduct::evaluate's.
  template <Accuracy kAccuracy = Accuracy::Full, std::size_t N>
  void evaluate(const std::array<Real, N>& delta, std::array<Real, N>& out) const {
    phase_.template evaluate<kAccuracy>(delta, out);
    if (!(depth_scale_ > 0)) return;
    for (std::size_t j = 0; j < N; ++j)
      out[j] *= detail::SegmentTransmittance<kAccuracy>(SinCosLanes<kAccuracy>(delta[j] / 2), pole_, depth_scale_);
  }

  bool point_lobe_flat() const { return phase_.point_lobe_flat(); }
  Real point_peak() const { return phase_.point_peak(); }
  const PhaseProduct<Real>& phase() const { return phase_; }

  // The fit's split points: the point lobe's peak (as Novák's), and where the segment lobe x
  // transmittance peaks inside the interval. For g < 0 the segment lobe grows towards the
  // far pole while the transmittance falls, so their product peaks inside; a fit that
  // misses that peak puts a tiny density under most of the integral (docs/maths.md#full-product).
  template <int kSize>
  struct Lanes;

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
  // lobe's denominator (1 + g)^2 + 4 |g| c^2 (g < 0). Along x the product rises where the
  // left side is larger; its maximum is the smaller positive root in c. Newton from the
  // root of the leading terms, 12 |g| c^3 = sigma_t h (1 + g)^2, which lies below it, until
  // a step is below 1e-2 c (the convergence is quadratic: the error left is ~1e-4 c,
  // finer than a node's position needs; over the benchmark's queries the peak moves by at
  // most 1.1e-4 of the interval against a solve to 1e-7). Returns the peak's offset, or -1
  // when the product has no interior peak.
  Real SegmentTransmittancePeak() const {
    Real g = phase_.segment_g();
    if (!(g < 0) || !(sigma_h_ > 0)) return -1;
    Real a = -g, k = 12 * a, base = Sqr(1 + g);
    Real c = CbrtLanes(sigma_h_ * base / k);
    // The peak lies before the interval when c already exceeds cos(x_a / 2) = pole_.cos.
    if (!(c < pole_.cos)) return -1;
    bool converged = false;
    for (int i = 0; i < 8 && c < 1 && !converged; ++i) {
      // f and s f' (s = sin y > 0: the same sign, and no division by s).
      Real s = std::sqrt(1 - c * c);
      Real f = k * s * c * c * c - sigma_h_ * (base + 4 * a * c * c);
      Real s_df = k * c * c * (3 - 4 * c * c) - 8 * a * sigma_h_ * c * s;
      if (!(s_df > 0)) return -1;  // past the maximum of the left side: no crossing from below
      Real step = s * f / s_df;
      c -= step;
      converged = std::abs(step) <= Real(1e-2) * c;
    }
    if (!converged || !(c > 0 && c < 1)) return -1;
    return 2 * Atan2Lanes(std::sqrt(1 - c * c), c) + phase_.lower_pole();
  }

 private:
  PhaseProduct<Real> phase_;
  SinCosPair<Real> pole_;  // of half the lower pole's offset, -x_a / 2
  Real sigma_h_;
  Real depth_scale_;  // sigma_t h / cos(x_a / 2)
  Real width_;
};

// The targets of a batch's camera steps in lanes: the phase product's (PhaseProduct::Lanes,
// the base) times the transmittance, what the constructor, evaluate() and splits() compute,
// lane by lane in the same operations (square roots by Newton steps: within 3 ulp). The
// peak's Newton solve runs its eight steps in every lane, each lane keeping its iterate once
// it converged.
template <typename Real>
template <int kSize>
struct FullProductTarget<Real>::Lanes : PhaseProduct<Real>::template Lanes<kSize> {
  using Phase = typename PhaseProduct<Real>::template Lanes<kSize>;
  using Phase::g, Phase::lower, Phase::width;
  Real pole_sin[kSize], pole_cos[kSize], sigma_h[kSize], depth_scale[kSize];

  template <Accuracy kAccuracy>
  void build(const detail::AngleFrameLanes<Real, kSize>& frames, const Real* axis_x, const Real* axis_y, const Real* axis_z,
             Vec3<Real> dir, Real segment_g, Real sigma_t, int lanes) {
    Phase::template build<kAccuracy>(frames, axis_x, axis_y, axis_z, dir, segment_g, sigma_t, lanes);
    for (int i = 0; i < lanes; ++i) {
      const SinCosPair<Real> pole = SinCosLanes(lower[i] / 2);
      pole_sin[i] = pole.sin, pole_cos[i] = pole.cos;
      sigma_h[i] = sigma_t * frames.h[i];
      depth_scale[i] = sigma_h[i] / pole.cos;
    }
  }

  template <Accuracy kAccuracy>
  void evaluate(int lanes, const Real* delta, Real* out) const {
    Phase::template evaluate<kAccuracy>(lanes, delta, out);
    for (int i = 0; i < lanes; ++i) {
      const Real transmittance = detail::SegmentTransmittance<kAccuracy>(SinCosLanes<kAccuracy>(delta[i] / 2),
                                                                         {pole_sin[i], pole_cos[i]}, depth_scale[i]);
      out[i] = SelectLanes(depth_scale[i] > 0, out[i] * transmittance, out[i]);
    }
  }

  void splits(int lanes, Real (*split)[kSize], int* count) const {
    Phase::splits(lanes, split, count);
    Real peak[kSize];
    SegmentTransmittancePeaks(lanes, peak);
    for (int i = 0; i < lanes; ++i) {
      const Real s0 = split[0][i], p = peak[i];
      const bool one = count[i] == 1;
      const bool add = (p > 0) & (p < width[i]) & !(one & (std::abs(p - s0) <= width[i] * Real(1e-3)));
      split[0][i] = SelectLanes(add & (!one | (p < s0)), p, s0);
      split[1][i] = SelectLanes(one & (p < s0), s0, p);
      count[i] += static_cast<int>(add);
    }
  }

 private:
  // SegmentTransmittancePeak() of every lane (-1: none).
  void SegmentTransmittancePeaks(int lanes, Real* peak) const {
    for (int i = 0; i < lanes; ++i) peak[i] = -1;
    if (!(g < 0)) return;
    const Real a = -g, k = 12 * a, base = Sqr(1 + g);
    // State per lane, as wide as the floats (a loop mixing bytes with them stays scalar):
    // 1 while iterating, 0 once converged, -1 when it has no peak.
    Real c[kSize];
    std::int32_t state[kSize];
    for (int i = 0; i < lanes; ++i) {
      c[i] = CbrtLanes(sigma_h[i] * base / k);
      state[i] = ((sigma_h[i] > 0) & (c[i] < pole_cos[i])) ? 1 : -1;
    }
    for (int step = 0; step < 8; ++step)
      for (int i = 0; i < lanes; ++i) {
        const Real x = c[i], s = SqrtLanes(1 - x * x);
        const Real f = k * s * x * x * x - sigma_h[i] * (base + 4 * a * x * x);
        const Real s_df = k * x * x * (3 - 4 * x * x) - 8 * a * sigma_h[i] * x * s;
        const bool active = (state[i] == 1) & (x < 1);
        const Real next = x - s * f / s_df;
        const bool rising = s_df > 0;
        c[i] = SelectLanes(active & rising, next, x);
        const bool converged = std::abs(s * f / s_df) <= Real(1e-2) * next;
        const std::int32_t stepped = std::int32_t(rising) * (2 - std::int32_t(converged)) - 1;  // 0, 1 or -1
        state[i] += std::int32_t(active) * (stepped - state[i]);
      }
    for (int i = 0; i < lanes; ++i) {
      const bool found = (state[i] == 0) & (c[i] > 0) & (c[i] < 1);
      peak[i] = SelectLanes(found, 2 * Atan2Lanes(SqrtLanes(1 - c[i] * c[i]), c[i]) + lower[i], Real(-1));
    }
  }
};

}  // namespace vrlis
