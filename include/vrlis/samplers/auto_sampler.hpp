#pragma once
// `auto`: no more model than a query needs. Per query, a cheap bound on equiangular
// sampling's relative variance decides between equiangular sampling (Kulla and Fajardo
// 2012) and the FullProduct fit (docs/maths.md#auto).
//
// The bound: for a target f with m <= f <= M on the interval, uniform sampling has relative
// variance W Int f^2 / (Int f)^2 - 1 <= (M - m)^2 / (4 M m) (Kantorovich's inequality), a
// function of the ratio rho = M / m alone. The target is a product of the segment lobe, the
// point lobe and the transmittance, so rho is at most the product of their own ratios, each
// exact and cheap: the segment lobe is monotone in theta (its cosine is -sin theta), the
// point lobe is extreme at the interval's ends or at its peak or antipode when inside, and
// the transmittance falls monotonically from tmin to tmax.
//
// The fit is kept where the bound exceeds kFitThreshold: a FullProduct gather costs about
// twice an equiangular one (docs/bench.md), so the fit pays for itself once equiangular's
// relative variance may exceed 1 (the two-step estimator's variance scales by 1 + V2).
#include <optional>
#include <string_view>
#include <type_traits>

#include "equiangular.hpp"
#include "full_product.hpp"

namespace vrlis {

// An upper bound of the ratio max / min of the full target (phase product x transmittance)
// over the query's angle interval; infinity when the target can vanish in it.
template <typename Real>
Real TargetRangeRatio(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom, const PhaseProduct<Real>& phase) {
  Real w = dom.width();
  Real s0 = phase.segment_lobe(0), s1 = phase.segment_lobe(w);
  Real ratio = std::max(s0, s1) / std::min(s0, s1);
  if (!phase.point_lobe_flat()) {
    Real p0 = phase.point_lobe(0), p1 = phase.point_lobe(w), hi = std::max(p0, p1), lo = std::min(p0, p1);
    Real peak = phase.point_peak();  // the peak (or, for g < 0, the backward peak) nearest the interval
    for (Real x : {peak, peak - kPi<Real>, peak + kPi<Real>})
      if (x > 0 && x < w) {
        Real v = phase.point_lobe(x);
        hi = std::max(hi, v);
        lo = std::min(lo, v);
      }
    ratio *= hi / lo;
  }
  if (q.sigma_t > 0) {
    if (!std::isfinite(q.tmax)) return std::numeric_limits<Real>::infinity();
    // Optical depth from tmin to tmax along the segment plus the change of the distance to p.
    Real depth = (q.tmax - q.tmin) + Length(q.point - (q.origin + q.tmax * q.dir)) -
                 Length(q.point - (q.origin + q.tmin * q.dir));
    ratio *= std::exp(q.sigma_t * std::max(depth, Real(0)));
  }
  return ratio > 0 ? ratio : std::numeric_limits<Real>::infinity();  // NaN (0 / 0) too
}

// Kantorovich's bound on uniform sampling's relative variance for a target ratio rho.
template <typename Real>
Real UniformVarianceBound(Real rho) {
  return std::isfinite(rho) ? Sqr(rho - 1) / (4 * rho) : std::numeric_limits<Real>::infinity();
}

template <typename R>
class AutoAngle {
 public:
  using Real = R;
  static constexpr Real kFitThreshold = 1;
  using Fit = std::remove_cv_t<std::remove_reference_t<decltype(std::declval<FullProduct<Real>>().distribution())>>;

  AutoAngle(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom) : uniform_(q, dom) {
    FullProductTarget<Real> target(q, dom);  // built once: the bound reads its lobes, the fit uses it
    if (UniformVarianceBound(TargetRangeRatio(q, dom, target.phase())) > kFitThreshold) fit_.emplace(target, dom.width());
  }

  bool fitted() const { return fit_.has_value(); }
  Real sample(Real u) const { return fit_ ? fit_->sample(u) : uniform_.sample(u); }
  Real pdf(Real delta) const { return fit_ ? fit_->pdf(delta) : uniform_.pdf(delta); }
  Real cdf(Real delta) const { return fit_ ? fit_->cdf(delta) : uniform_.cdf(delta); }
  SegmentSample<Real> sample_pdf(Real u) const { return fit_ ? fit_->sample_pdf(u) : uniform_.sample_pdf(u); }

 private:
  UniformAngle<Real> uniform_;
  std::optional<Fit> fit_;
};

template <typename Real = float>
using Auto = SegmentSampler<AutoAngle<Real>>;

// Its entry in the run-time sampler tables (method.hpp).
struct AutoEntry {
  static constexpr std::string_view kName = "auto";
  template <typename Real>
  using Sampler = Auto<Real>;
};

}  // namespace vrlis
