#pragma once
// The medium-to-medium VRL gather (docs/maths.md#estimators, Novák et al. 2012): a point on
// the VRL by step one, then a point on the camera segment by step two, both chosen at run
// time (method.hpp). The integrand, per unit length on both segments, is
//   sigma_s^2 rho(w_c . w) rho(-w_l . w) T(t - tmin) T(v) T(|y - x|) / |y - x|^2,
// w the unit vector from the camera point x(t) to the VRL point y(v).
#include "../method.hpp"
#include "gather_sample.hpp"

namespace vrlis {

// The camera step's query for the VRL point y: the camera segment seen from y.
template <typename Real>
SegmentQuery<Real> CameraStepQuery(const MediumGatherQuery<Real>& q, Vec3<Real> y) {
  return MediumToMediumQuery(q.camera.origin, q.camera.dir, q.camera.tmin, q.camera.tmax, y, q.vrl.dir, q.medium.g,
                             q.medium.sigma_t);
}

// The integrand at (t, v) without visibility, and its connection transmittance.
template <typename Real>
Real MediumGatherIntegrand(const MediumGatherQuery<Real>& q, Real t, Real v, Real* transmittance = nullptr) {
  Vec3<Real> x = q.camera.at(t), y = q.vrl.at(v), w = y - x;
  Real r2 = Dot(w, w);
  if (!(r2 > 0)) return 0;
  Real r = std::sqrt(r2);
  Vec3<Real> wh = (Real(1) / r) * w;
  const Medium<Real>& m = q.medium;
  Real connection = std::exp(-m.sigma_t * r);
  if (transmittance) *transmittance = connection;
  return m.sigma_s * m.sigma_s * HenyeyGreenstein(m.g, Clamp(Dot(q.camera.dir, wh), Real(-1), Real(1))) *
         HenyeyGreenstein(m.g, Clamp(-Dot(q.vrl.dir, wh), Real(-1), Real(1))) *
         std::exp(-m.sigma_t * ((t - q.camera.tmin) + v)) * connection / r2;
}

// One estimate from two uniform numbers: u_vrl for step one, u_camera for step two.
template <typename Real>
GatherSample<Real> SampleMediumGather(GatherMethod method, const MediumGatherQuery<Real>& q, Real u_vrl,
                                      Real u_camera) {
  if (Validate(q) != QueryError::None) return {};
  return VrlSamplers::With(method.vrl, q, [&](const auto& step_one) {
    SegmentSample<Real> v = step_one.sample_pdf(u_vrl);
    if (!detail::Usable(v)) return GatherSample<Real>{};
    Vec3<Real> y = q.vrl.at(v.t);
    return CameraSamplers::With(method.camera, ValidQuery{}, CameraStepQuery(q, y), [&](const auto& step_two) {
      SegmentSample<Real> t = step_two.sample_pdf(u_camera);
      if (!detail::Usable(t)) return GatherSample<Real>{};
      GatherSample<Real> s;
      s.camera_point = q.camera.at(t.t);
      s.light_point = y;
      s.t = t.t;
      s.pdf_t = t.pdf;
      s.v = v.t;
      s.pdf_v = v.pdf;
      Real f = MediumGatherIntegrand(q, t.t, v.t, &s.transmittance);
      return detail::Finish(s, f, t.pdf * v.pdf);
    });
  });
}

}  // namespace vrlis
