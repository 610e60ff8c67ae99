#pragma once
// Optional adapter: builds vrlis queries from GLM vectors (needs GLM on the include path);
// the vectors themselves convert by xyz.hpp, as any type with x, y, z.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "vrlis.hpp"

namespace vrlis {

// Medium to medium: the camera segment origin + t dir, t in [tmin, tmax], gathering from the
// VRL point vrl_point on a VRL travelling along vrl_dir; both scatter with HG(g).
template <typename Real>
SegmentQuery<Real> MediumQuery(const glm::vec<3, Real>& origin, const glm::vec<3, Real>& dir, Real tmin, Real tmax,
                               const glm::vec<3, Real>& vrl_point, const glm::vec<3, Real>& vrl_dir, Real g,
                               Real sigma_t = 0) {
  return MediumToMediumQuery(FromXyz(origin), FromXyz(glm::normalize(dir)), tmin, tmax, FromXyz(vrl_point),
                             FromXyz(glm::normalize(vrl_dir)), g, sigma_t);
}

// Medium to surface: the VRL origin + t dir, t in [tmin, tmax], seen from a diffuse surface
// point with unit normal (facing the side the light arrives from).
template <typename Real>
SegmentQuery<Real> SurfaceQuery(const glm::vec<3, Real>& vrl_origin, const glm::vec<3, Real>& vrl_dir, Real tmin,
                                Real tmax, const glm::vec<3, Real>& surface_point, const glm::vec<3, Real>& normal,
                                Real g, Real sigma_t = 0) {
  return MediumToSurfaceQuery(FromXyz(vrl_origin), FromXyz(glm::normalize(vrl_dir)), tmin, tmax,
                              FromXyz(surface_point), FromXyz(glm::normalize(normal)), g, sigma_t);
}

// Step one: a point on the VRL vrl_origin + v vrl_dir, v in [0, length], for the camera line.
template <typename Real>
VrlPointQuery<Real> VrlPointQueryFor(const glm::vec<3, Real>& vrl_origin, const glm::vec<3, Real>& vrl_dir,
                                     Real length, const glm::vec<3, Real>& camera_origin,
                                     const glm::vec<3, Real>& camera_dir) {
  return {FromXyz(vrl_origin), FromXyz(glm::normalize(vrl_dir)), Real(0), length, FromXyz(camera_origin),
          FromXyz(glm::normalize(camera_dir))};
}

}  // namespace vrlis
