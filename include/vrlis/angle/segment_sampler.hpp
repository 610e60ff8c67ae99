#pragma once
// Every camera-segment sampler is a density over delta = theta - theta_a carried back to
// the segment parameter t. This adapter does the carrying once, for all of them. A
// Distribution offers sample(u), pdf(delta), cdf(delta) and sample_pdf(u) -> {delta, pdf}
// over [0, width].
//
// Contract (tested in tests/):
// - valid() is Validate(query) == QueryError::None. For an invalid query, sample() and
//   invert() return NaN and pdf() returns 0: a checkable outcome, never undefined behaviour.
// - For a valid query, sample(u) for u in [0, 1] is finite and inside [tmin, tmax] (an
//   unbounded segment samples below the largest finite Real); pdf(t) is finite, zero outside
//   [tmin, tmax] and positive inside wherever the target is, except where the density is
//   below the smallest normal Real (the far end of an unbounded segment, where a sample
//   clamped to the largest Real gets pdf 0). A sample with pdf 0 contributes nothing.
// - invert(t) is the CDF of the sampled distribution, so invert(sample(u)) == u up to
//   rounding for every sampler whose sample() is the CDF's inverse (all but CauchyMixture,
//   which selects a component first; its round trip holds in distribution). Rounding: u is
//   among the CDF's values within a few ulps of t and of its angle offset; where the density
//   changes by orders of magnitude within an ulp of t (a peak narrower than that ulp), that
//   is far more than pdf(t) times an ulp. When p lies on
//   the segment's line up to rounding (domain().on_line()), the density is a spike as wide
//   as that rounding and the round trip holds only to the resolution of t.
// - A segment shorter than min<Real> / epsilon<Real> (zero length included), or whose angle
//   width underflows, has no representable density: sample() returns tmin, pdf() returns 0 and
//   invert() returns 0. Its integral is (numerically) zero; skip it.
#include <limits>
#include <type_traits>
#include <utility>

#include "angle_domain.hpp"

namespace vrlis {

template <typename Distribution>
class SegmentSampler {
 public:
  using Real = typename Distribution::Real;

  template <typename... FitArgs>
  explicit SegmentSampler(const SegmentQuery<Real>& q, FitArgs&&... fit_args)
      : SegmentSampler(Checked{Validate(q)}, q, std::forward<FitArgs>(fit_args)...) {}
  SegmentSampler(ValidQuery, const SegmentQuery<Real>& q) : SegmentSampler(Checked{QueryError::None}, q) {}
  // With q's angle domain reduced elsewhere (a batch reduces many in lanes: gather/*_gather.hpp).
  SegmentSampler(ValidQuery, const SegmentQuery<Real>& q, const AngleDomain<Real>& domain)
      : SegmentSampler(QueryError::None, q, domain) {}

  bool valid() const { return error_ == QueryError::None; }
  QueryError error() const { return error_; }
  const AngleDomain<Real>& domain() const { return domain_; }
  const Distribution& distribution() const { return dist_; }

  Real sample(Real u) const {
    if (!usable_) return valid() ? domain_.tmin() : kNaN;
    return domain_.t_at(dist_.sample(u));
  }

  Real pdf(Real t) const {
    if (!usable_ || !(t >= domain_.tmin() && t <= domain_.tmax())) return 0;
    return dist_.pdf(domain_.offset_at(t)) * domain_.dtheta_dt(t);
  }

  // sample(u) and pdf() of it in one call (pbrt's Sample(u, &pdf)): the distribution's
  // density comes from what its sampling computed and the Jacobian from the sine and cosine
  // that carry the offset to t, so no offset or slope is recomputed from t.
  SegmentSample<Real> sample_pdf(Real u) const {
    if (!usable_) return {sample(u), 0};
    SegmentSample<Real> d = dist_.sample_pdf(u);
    AnglePoint<Real> p = domain_.point_at(d.t);
    return {p.t, d.pdf * p.dtheta_dt};
  }

  // sample_pdf's first half: the distribution's angle offset and its density over the offset
  // (pdf 0 where nothing is sampled), which domain().point_at carries to t; a batch carries
  // many at once in lanes (detail::PointAtOffset).
  SegmentSample<Real> sample_offset(Real u) const { return usable_ ? dist_.sample_pdf(u) : SegmentSample<Real>{}; }

  Real invert(Real t) const {
    if (!usable_) return valid() ? Real(0) : kNaN;
    return Clamp(dist_.cdf(domain_.offset_at(t)), Real(0), Real(1));
  }

 private:
  struct Checked {
    QueryError error;
  };
  template <typename... FitArgs>
  SegmentSampler(Checked checked, const SegmentQuery<Real>& q, FitArgs&&... fit_args)
      : SegmentSampler(checked.error, q, AngleDomain<Real>(checked.error == QueryError::None ? q : Fallback()),
                       std::forward<FitArgs>(fit_args)...) {}
  template <typename... FitArgs>
  SegmentSampler(QueryError error, const SegmentQuery<Real>& q, const AngleDomain<Real>& domain, FitArgs&&... fit_args)
      : error_(error),
        domain_(domain),
        usable_(valid() && domain_.width() >= std::numeric_limits<Real>::min() &&
                RepresentableLength(domain_.tmax() - domain_.tmin())),
        dist_(usable_ ? q : Fallback(), usable_ ? domain_ : AngleDomain<Real>(Fallback()),
              std::forward<FitArgs>(fit_args)...) {}
  // (Distributions copy what they need from the domain; they keep no reference to it.)

  static constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
  // Fitting on invalid input could reach undefined behaviour (NaN to int); fit this instead.
  static SegmentQuery<Real> Fallback() {
    SegmentQuery<Real> q;
    q.dir = {0, 0, 1};
    q.tmax = 1;
    q.point = {1, 0, 0};
    return q;
  }

  QueryError error_;
  AngleDomain<Real> domain_;
  bool usable_;  // valid, with a representable density
  Distribution dist_;
};

// The static interface every camera-segment sampler S offers, checked at compile time:
// S(const SegmentQuery<S::Real>&), and Real sample(Real), pdf(Real), invert(Real) const.
template <typename S, typename = void>
struct IsSegmentSampler : std::false_type {};

template <typename S>
struct IsSegmentSampler<
    S, std::enable_if_t<std::is_constructible_v<S, const SegmentQuery<typename S::Real>&> &&
                        std::is_same_v<decltype(std::declval<const S&>().sample(typename S::Real{})), typename S::Real> &&
                        std::is_same_v<decltype(std::declval<const S&>().pdf(typename S::Real{})), typename S::Real> &&
                        std::is_same_v<decltype(std::declval<const S&>().invert(typename S::Real{})), typename S::Real>>>
    : std::true_type {};

}  // namespace vrlis
