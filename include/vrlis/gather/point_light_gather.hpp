#pragma once
// Single scattering from an isotropic point light along a camera segment
// (docs/maths.md#estimators). The integrand per unit length, per unit intensity, is
//   sigma_s rho(w_c . w) T(t - tmin) T(|l - x|) / |l - x|^2,
// w the unit vector from the camera point x(t) to the light l.
#include "../method.hpp"
#include "gather_sample.hpp"

namespace vrlis {

// The camera step's query: the light seen from the camera segment.
template <typename Real>
SegmentQuery<Real> CameraStepQuery(const PointLightGatherQuery<Real>& q) {
  return PointLightQuery(q.camera.origin, q.camera.dir, q.camera.tmin, q.camera.tmax, q.light, q.medium.g,
                         q.medium.sigma_t);
}

template <typename Real>
IntegrandFactors<Real> PointLightGatherFactors(const PointLightGatherQuery<Real>& q, Real t) {
  Vec3<Real> x = q.camera.at(t), w = q.light - x;
  Real r2 = Dot(w, w);
  if (!(r2 > 0)) return {};
  Real r = std::sqrt(r2);
  Real rho = HenyeyGreenstein(q.medium.g, Clamp(Dot(q.camera.dir, w) / r, Real(-1), Real(1)));
  return {rho / r2, (t - q.camera.tmin) + r, r, 1};
}

template <typename Real>
Real PointLightGatherIntegrand(const PointLightGatherQuery<Real>& q, Real t, Real* transmittance = nullptr) {
  return PointLightGatherFactors(q, t).value(q.medium, transmittance);
}

template <typename Real>
GatherSample<Real> SamplePointLightGather(SegmentChoice method, const PointLightGatherQuery<Real>& q, Real u) {
  if (Validate(q) != QueryError::None) return {};
  return SegmentSamplers::With(method, ValidQuery{}, CameraStepQuery(q), [&](const auto& sampler) {
    SegmentSample<Real> t = sampler.sample_pdf(u);
    if (!detail::Usable(t)) return GatherSample<Real>{};
    GatherSample<Real> s;
    s.camera_point = q.camera.at(t.t);
    s.light_point = q.light;
    s.t = t.t;
    s.pdf_t = t.pdf;
    detail::Finish(s, PointLightGatherFactors(q, t.t), q.medium, t.pdf);
    return s;
  });
}

}  // namespace vrlis
