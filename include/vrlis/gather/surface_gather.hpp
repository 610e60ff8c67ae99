#pragma once
// The medium-to-surface VRL gather (docs/maths.md#estimators): a point on the VRL seen from
// a diffuse surface point through its clamped cosine. The integrand per unit VRL length is
//   sigma_s rho(-w_l . w) max(0, n . w) / pi T(v) T(|y - p|) / |y - p|^2,
// w the unit vector from the surface point p to the VRL point y(v); the renderer multiplies
// by the surface's albedo.
#include <algorithm>
#include <optional>
#include <type_traits>

#include "../core/dispatch.hpp"
#include "../method.hpp"
#include "gather_sample.hpp"

namespace vrlis {

// The VRL seen from the surface point: the query the VRL sampler is built from.
template <typename Real>
SegmentQuery<Real> VrlStepQuery(const SurfaceGatherQuery<Real>& q) {
  return MediumToSurfaceQuery(q.vrl.origin, q.vrl.dir, Real(0), q.vrl.length, q.point, q.normal, q.medium.g,
                              q.medium.sigma_t);
}

template <typename Real>
IntegrandFactors<Real> SurfaceGatherFactors(const SurfaceGatherQuery<Real>& q, Real v) {
  Vec3<Real> y = q.vrl.at(v), w = y - q.point;
  Real r2 = Dot(w, w);
  if (!(r2 > 0)) return {};
  Real r = std::sqrt(r2);
  Vec3<Real> wh = (Real(1) / r) * w;
  Real cos = Dot(q.normal, wh);
  if (!(cos > 0)) return {};
  Real rho = HenyeyGreenstein(q.medium.g, Clamp(-Dot(q.vrl.dir, wh), Real(-1), Real(1)));
  return {rho * cos * kInvPi<Real> / r2, v + r, r, 1};
}

template <typename Real>
Real SurfaceGatherIntegrand(const SurfaceGatherQuery<Real>& q, Real v, Real* transmittance = nullptr) {
  return SurfaceGatherFactors(q, v).value(q.medium, transmittance);
}

// The gather's outcome for the VRL sample v (usable or not).
template <typename Real>
[[gnu::always_inline]] inline GatherSample<Real> FinishSurfaceGather(const SurfaceGatherQuery<Real>& q,
                                                                     SegmentSample<Real> v) {
  if (!detail::Usable(v)) return {};
  GatherSample<Real> s;
  s.camera_point = q.point;
  s.light_point = q.vrl.at(v.t);
  s.v = v.t;
  s.pdf_v = v.pdf;
  detail::Finish(s, SurfaceGatherFactors(q, v.t), q.medium, v.pdf);
  return s;
}

// One estimate with the sampler fixed at compile time, for a query the caller has validated
// (flattened, as SampleMediumGather's typed form).
template <typename Sampler, typename Real>
[[gnu::flatten]] GatherSample<Real> SampleSurfaceGather(ValidQuery, const SurfaceGatherQuery<Real>& q, Real u) {
  return FinishSurfaceGather(q, Sampler(ValidQuery{}, VrlStepQuery(q)).sample_pdf(u));
}

// Many VRLs seen from one surface point, a renderer's inner loop: out[i] is
// SampleSurfaceGather for {point, normal, vrls[i], medium} with u[i] (each query valid), run
// in phases over batches as SampleMediumGathers (fits, samples, integrands), one fit for a
// run of equal VRLs (a split gather's samples): same numbers. measure_mixture: as
// SampleMediumGathers.
namespace detail {
template <typename Sampler, typename Real>
[[gnu::flatten]] void SampleSurfaceGathersAsBuilt(Vec3<Real> point, Vec3<Real> normal, const Medium<Real>& medium,
                                                  const VrlSegment<Real>* vrls, int count, const Real* u,
                                                  GatherSample<Real>* out, bool measure_mixture) {
  constexpr int kBatch = 8;  // enough independent gathers to fill the processor's reordering window
  for (int first = 0; first < count; first += kBatch) {
    int n = std::min(kBatch, count - first);
    std::optional<Sampler> fit[kBatch];
    int fit_of[kBatch];  // the fit sample i draws from
    for (int i = 0; i < n; ++i) {
      if (i > 0 && SameVrl(vrls[first + i], vrls[first + fit_of[i - 1]])) {
        fit_of[i] = fit_of[i - 1];
        continue;
      }
      fit_of[i] = i;
      fit[i].emplace(ValidQuery{}, VrlStepQuery(SurfaceGatherQuery<Real>{point, normal, vrls[first + i], medium}));
    }
    SegmentSample<Real> v[kBatch];
    Real over[kBatch] = {}, over_mixture[kBatch] = {};  // of auto's samples
    for (int i = 0; i < n; ++i) {
      v[i] = fit[fit_of[i]]->sample_pdf(u[first + i]);
      if constexpr (std::is_same_v<Sampler, AutoEntry::Sampler<Real>>) {
        over[i] = detail::OverEquiangular(fit[fit_of[i]]->domain(), v[i]);
        if (measure_mixture)
          over_mixture[i] = detail::OverDensity<CauchyMixtureAngle<Real>>(
              fit[fit_of[i]]->domain(), VrlStepQuery(SurfaceGatherQuery<Real>{point, normal, vrls[first + i], medium}), v[i]);
      }
    }
    for (int i = 0; i < n; ++i) {
      GatherSample<Real>& g = out[first + i];
      g = FinishSurfaceGather(SurfaceGatherQuery<Real>{point, normal, vrls[first + i], medium}, v[i]);
      g.over_equiangular = g.contributes() ? over[i] : Real(0);
      g.over_mixture = g.contributes() ? over_mixture[i] : Real(0);
    }
  }
}
}  // namespace detail

// The batch above, on the widest vector lanes the processor has (core/dispatch.hpp);
// `widest` false: as built.
template <typename Sampler, typename Real>
void SampleSurfaceGathers(ValidQuery, Vec3<Real> point, Vec3<Real> normal, const Medium<Real>& medium,
                          const VrlSegment<Real>* vrls, int count, const Real* u, GatherSample<Real>* out,
                          bool measure_mixture = false, bool widest = true) {
  detail::WithWidestLanes(
      [&] { detail::SampleSurfaceGathersAsBuilt<Sampler>(point, normal, medium, vrls, count, u, out, measure_mixture); },
      widest);
}

// The same with the sampler chosen at run time; any query (an invalid one samples nothing).
template <typename Real>
GatherSample<Real> SampleSurfaceGather(SegmentChoice method, const SurfaceGatherQuery<Real>& q, Real u) {
  if (Validate(q) != QueryError::None) return {};
  return SegmentSamplers::WithEntry(method, [&](auto entry) {
    return SampleSurfaceGather<typename decltype(entry)::template Sampler<Real>>(ValidQuery{}, q, u);
  });
}

}  // namespace vrlis
