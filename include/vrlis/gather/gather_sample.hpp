#pragma once
// The outcome of one gather estimate: the sampled points, their densities and the weight
// f / pdf of everything except visibility and the light's power. A renderer traces one
// occlusion ray between camera_point and light_point and multiplies.
#include "../core/gather_query.hpp"

namespace vrlis {

template <typename Real>
struct GatherSample {
  Vec3<Real> camera_point{}, light_point{};  // the ends of the occlusion ray
  Real t = 0, pdf_t = 0;  // on the camera segment (medium and point-light gathers)
  Real v = 0, pdf_v = 0;  // on the VRL (medium and surface gathers)
  // exp(-sigma_t |light_point - camera_point|), included in weight. A renderer whose medium
  // does not fill the connection replaces it by its own transmittance (weight / transmittance).
  Real transmittance = 0;
  Real weight = 0;  // 0: nothing to trace

  bool contributes() const { return weight > 0; }
};

namespace detail {
template <typename Real>
bool Usable(SegmentSample<Real> s) {
  return s.pdf > 0 && std::isfinite(s.pdf) && std::isfinite(s.t);
}

// Fills the connection and the weight f / pdf from the integrand f; any non-finite or
// non-positive outcome becomes "nothing to trace" (never a NaN in an image).
template <typename Real>
GatherSample<Real> Finish(GatherSample<Real> s, Real f, Real pdf) {
  s.weight = f / pdf;
  if (!(s.weight > 0) || !std::isfinite(s.weight)) s.weight = 0;
  return s;
}
}  // namespace detail

}  // namespace vrlis
