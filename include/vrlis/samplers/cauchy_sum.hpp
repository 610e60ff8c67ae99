#pragma once
// The 2023 TU Wien thesis's solution 1 (docs/maths.md#cauchy-sum): p(theta) proportional to C1(theta) + C2(theta), normalised jointly.
//
// The CDF is a sum of two arctangents; the sum of two arctangents is the argument of a
// product of two complex numbers, so F(delta) = u is a quadratic in delta. Of its two roots
// the wanted one is where the argument crosses its target increasing, i.e. where the
// quadratic's slope is +sqrt(disc).
#include <algorithm>
#include <string_view>
#include <type_traits>

#include "../angle/segment_sampler.hpp"
#include "cauchy_lobe.hpp"

namespace vrlis {

template <typename R>
class CauchySumAngle {
 public:
  using Real = R;
  CauchySumAngle(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom)
      : CauchySumAngle(CauchyLobes<Real>(PhaseProduct<Real>(q, dom)), dom.width()) {}
  CauchySumAngle(const CauchyLobes<Real>& fit, Real width) : fit_(fit), width_(width) {
    for (int k = 0; k < fit_.count; ++k) mass_ += fit_.lobe[k].mass();
  }

  // A batch's fits and samples in vector lanes (CauchyLobesLanes): out[i] is sample_pdf(u[i])
  // of lane i's query, to rounding. The two-lobe quadratic runs in the lanes, its sines too
  // (WidenedSinCosLanes: the same order of samples as one query at a time), and so does a lane
  // without lobes (g = 0); one with a single lobe (the other flat) is sampled as one query after.
  template <int kSize>
  using TargetLanes = typename PhaseProduct<Real>::template Lanes<kSize, false>;
  template <int kSize>
  static void SampleLanes(const TargetLanes<kSize>& target, const Real* u, int lanes, SegmentSample<Real>* out) {
    const CauchyLobesLanes<Real, kSize> fits(target, lanes);
    Real turn[kSize];
    for (int i = 0; i < lanes; ++i) {
      const Real w = target.width[i], mass = fits.mass[0][i] + fits.mass[1][i];
      turn[i] = Turn<true>(Centre<true>(fits.lobe(0, i, w), fits.lobe(1, i, w), w), u[i] * mass, mass, w);
    }
    Widened<Real> sin[kSize], cos[kSize];
    WidenedSinCosLanes(turn, lanes, sin, cos);
    for (int i = 0; i < lanes; ++i) {
      const Real w = target.width[i];
      const SegmentSample<Real> two = SampleQuadratic<true>(fits.lobe(0, i, w), fits.lobe(1, i, w), w,
                                                            fits.mass[0][i] + fits.mass[1][i], {sin[i], cos[i]});
      const bool none = fits.count[i] == 0;  // uniform, as sample_pdf (g = 0: every lane)
      out[i] = {SelectLanes(none, u[i] * w, two.t), SelectLanes(none, 1 / w, two.pdf)};
    }
    for (int i = 0; i < lanes; ++i)
      if (fits.count[i] == 1) out[i] = CauchySumAngle(fits.lobes(i, target.width[i]), target.width[i]).sample_pdf(u[i]);
  }

  Real sample(Real u) const {
    switch (fit_.count) {
      case 0: return u * width_;
      case 1: return fit_.lobe[0].inverse_primitive(u * mass_);
    }
    return sample_pdf(u).t;
  }

  // The two-lobe density from the offsets to both peaks the quadratic was written in.
  SegmentSample<Real> sample_pdf(Real u) const {
    if (fit_.count == 2) {
      const TruncatedCauchy<Real>&c1 = fit_.lobe[0], &c2 = fit_.lobe[1];
      const Real s = u * mass_;
      return SampleQuadratic<false>(c1, c2, width_, mass_,
                                    WidenedSinCos(Turn<false>(Centre<false>(c1, c2, width_), s, mass_, width_)));
    }
    Real delta = sample(u);
    return {delta, pdf(delta)};
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
  // Expanded about a point c (x = delta - c, e_k = c - mu_k), each primitive's increase is
  // arg z_k with z_k = (P_k + e_k x) + i gamma_k x, P_k = gamma_k^2 + e_k^2, so
  // F(delta) = s becomes Im(z1 z2 e^{-iK}) = a x^2 + b x + c0 = 0 with K = s - F(c).
  // c is the narrower peak if it lies inside the interval (coefficients of the size of its
  // scale: a narrow lobe far from theta_a keeps its digits) and otherwise the nearer end
  // (F(c) is then exactly 0 or the whole mass: a tiny interval keeps its digits).
  template <bool kLanes>
  [[gnu::always_inline]] static Real Centre(const TruncatedCauchy<Real>& c1, const TruncatedCauchy<Real>& c2, Real width) {
    return PickClamp<kLanes>(Pick<kLanes>(c1.scale() < c2.scale(), c1.location(), c2.location()), Real(0), width);
  }
  // The angle whose sine and cosine SampleQuadratic takes for s: s itself, or s - F(c) where
  // c is the far end (inside, F(c) is a rotation of them, not an arctangent).
  template <bool kLanes>
  [[gnu::always_inline]] static Real Turn(Real c, Real s, Real mass, Real width) {
    return Pick<kLanes>(c == width, s - mass, s);
  }
  // In float the root is solved in double: K is monotone in u, but a float solve of an
  // ill-conditioned quadratic is not, and where the density is low its errors reverse samples.
  // Returns the offset and its density (pdf()), the latter from x and the offsets e_k.
  // kLanes: branch-free, for a loop over a batch's samples.
  template <bool kLanes>
  [[gnu::always_inline]] static SegmentSample<Real> SampleQuadratic(const TruncatedCauchy<Real>& c1,
                                                                    const TruncatedCauchy<Real>& c2, Real width,
                                                                    Real mass, SinCosPair<Widened<Real>> e) {
    using W = Widened<Real>;
    const Real c = Centre<kLanes>(c1, c2, width);
    W e1 = W(c) - c1.location(), e2 = W(c) - c2.location(), g1 = c1.scale(), g2 = c2.scale();
    W p1 = g1 * g1 + e1 * e1, p2 = g2 * g2 + e2 * e2;
    // (cos K, sin K) up to a positive factor (the equation is homogeneous in them). Inside,
    // F(c) = arg z1(c) + arg z2(c) = arg w with w = z1(c) z2(c), z_k(c) = Re_k(c) + i c, so
    // e^{iK} is e^{is} rotated back by w: no arctangent for F(c).
    const bool inside = (c > 0) & (c < width);
    W r1 = g1 - W(c1.location()) * e1 * W(c1.inv_scale()), r2 = g2 - W(c2.location()) * e2 * W(c2.inv_scale());
    W re = r1 * r2 - W(c) * W(c), im = W(c) * (r1 + r2);
    W cs = Pick<kLanes>(inside, e.cos * re + e.sin * im, e.cos), sn = Pick<kLanes>(inside, e.sin * re - e.cos * im, e.sin);
    W a = (g2 * e1 + g1 * e2) * cs - (e1 * e2 - g1 * g2) * sn;
    W b = (g2 * p1 + g1 * p2) * cs - (p1 * e2 + p2 * e1) * sn;
    W c0 = -p1 * p2 * sn;
    // Keep b^2 - 4 a c0 finite and normal. A float query solved in double needs no scaling:
    // its scales lie between 64 eps width (width >= the smallest normal float) and
    // extent / sqrt(eps) (CauchyLobes), its offsets below 4 pi, so every p_k lies in
    // [1e-86, 2e9] and the discriminant's terms (~p^3) in [1e-259, 1e30]; in double they need it.
    if constexpr (std::is_same_v<W, Real>) {
      W inv_norm = 1 / std::max({std::abs(a), std::abs(b), std::abs(c0)});
      a *= inv_norm;
      b *= inv_norm;
      c0 *= inv_norm;
    }
    W root = PickSqrt<kLanes>(Pick<kLanes>(b * b - 4 * a * c0 > 0, b * b - 4 * a * c0, W(0)));
    // The root where the argument crosses K increasing, (-b + root) / (2a), in whichever
    // form does not cancel (selected, not branched: the sign of b is random across queries).
    const bool positive = b > 0;
    W x = Pick<kLanes>(positive, -2 * c0, root - b) / Pick<kLanes>(positive, b + root, 2 * a);
    Real delta = Real(c + x);
    // Clamped (NaN to 0): the density where it lands.
    const bool landed = (delta >= 0) & (delta <= width);
    delta = Pick<kLanes>(landed, delta, Pick<kLanes>(delta >= 0, width, Real(0)));
    x = Pick<kLanes>(landed, x, W(delta) - W(c));
    // gamma_k / ((delta - mu_k)^2 + gamma_k^2) for both lobes, over one division.
    W q1 = Sqr(e1 + x) + g1 * g1, q2 = Sqr(e2 + x) + g2 * g2;
    return {delta, Real((g1 * q2 + g2 * q1) / (q1 * q2 * W(mass)))};
  }

  CauchyLobes<Real> fit_;
  Real width_;
  Real mass_ = 0;
};

template <typename Real = float>
using CauchySum = SegmentSampler<CauchySumAngle<Real>>;

// Its entry in the run-time sampler tables (method.hpp).
struct CauchySumEntry {
  static constexpr std::string_view kName = "cauchy-sum";
  template <typename Real>
  using Sampler = CauchySum<Real>;
};

}  // namespace vrlis
