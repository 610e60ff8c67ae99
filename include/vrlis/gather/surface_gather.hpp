#pragma once
// The medium-to-surface VRL gather (docs/maths.md#estimators): a point on the VRL seen from
// a diffuse surface point through its clamped cosine. The integrand per unit VRL length is
//   sigma_s rho(-w_l . w) max(0, n . w) / pi T(v) T(|y - p|) / |y - p|^2,
// w the unit vector from the surface point p to the VRL point y(v); the renderer multiplies
// by the surface's albedo.
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
Real SurfaceGatherIntegrand(const SurfaceGatherQuery<Real>& q, Real v, Real* transmittance = nullptr) {
  Vec3<Real> y = q.vrl.at(v), w = y - q.point;
  Real r2 = Dot(w, w);
  if (!(r2 > 0)) return 0;
  Real r = std::sqrt(r2);
  Vec3<Real> wh = (Real(1) / r) * w;
  Real cos = Dot(q.normal, wh);
  if (!(cos > 0)) return 0;
  const Medium<Real>& m = q.medium;
  Real connection = std::exp(-m.sigma_t * r);
  if (transmittance) *transmittance = connection;
  return m.sigma_s * HenyeyGreenstein(m.g, Clamp(-Dot(q.vrl.dir, wh), Real(-1), Real(1))) * cos * kInvPi<Real> *
         std::exp(-m.sigma_t * v) * connection / r2;
}

// One estimate with the sampler fixed at compile time, for a query the caller has validated
// (flattened, as SampleMediumGather's typed form).
template <typename Sampler, typename Real>
[[gnu::flatten]] GatherSample<Real> SampleSurfaceGather(ValidQuery, const SurfaceGatherQuery<Real>& q, Real u) {
  SegmentSample<Real> v = Sampler(ValidQuery{}, VrlStepQuery(q)).sample_pdf(u);
  if (!detail::Usable(v)) return {};
  GatherSample<Real> s;
  s.camera_point = q.point;
  s.light_point = q.vrl.at(v.t);
  s.v = v.t;
  s.pdf_v = v.pdf;
  Real f = SurfaceGatherIntegrand(q, v.t, &s.transmittance);
  return detail::Finish(s, f, v.pdf);
}

// The same with the sampler chosen at run time; any query (an invalid one samples nothing).
template <typename Real>
GatherSample<Real> SampleSurfaceGather(Method method, const SurfaceGatherQuery<Real>& q, Real u) {
  if (Validate(q) != QueryError::None) return {};
  return CameraSamplers::WithEntry(method, [&](auto entry) {
    return SampleSurfaceGather<typename decltype(entry)::template Sampler<Real>>(ValidQuery{}, q, u);
  });
}

}  // namespace vrlis
