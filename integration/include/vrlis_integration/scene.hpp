#pragma once
// What the pipeline needs from a scene: closest hit and occlusion (abstract, implemented
// with Embree by the example), one homogeneous medium, materials, lights and a camera.
#include <memory>
#include <vector>

#include "light.hpp"
#include "material.hpp"
#include "medium.hpp"
#include "work.hpp"

namespace vrlis::integration {

struct SurfaceHit {
  float t = 0;
  Vec3f p{}, n{};  // n: unit geometric normal (pointing out of closed objects)
  int material = 0;
};

class Geometry {
 public:
  virtual ~Geometry() = default;
  // The closest surface along the ray in (kRayEpsilon, tmax).
  virtual bool Intersect(const Ray& ray, float tmax, SurfaceHit* hit) const = 0;
  // Whether a surface lies strictly between p0 and p1.
  virtual bool Occluded(Vec3f p0, Vec3f p1) const = 0;
};

// A pinhole at `position` looking down -z with +y up, horizontal field of view `fov_x`.
struct Camera {
  Vec3f position{};
  float fov_x = kPi / 2;
  // The ray through image point (x, y) in pixels (continuous, origin top left).
  Ray Generate(float x, float y, int width, int height) const {
    float half = std::tan(fov_x / 2);
    float px = (2 * x / width - 1) * half, py = (1 - 2 * y / height) * half * height / width;
    return {position, Normalize(Vec3f{px, py, -1})};
  }
};

struct Scene {
  std::shared_ptr<const Geometry> geometry;
  std::vector<Material> materials;
  HomogeneousMedium medium;
  Lights lights;
  Camera camera;

  // The rays, each counted as work on this thread (work.hpp).
  bool Intersect(const Ray& r, SurfaceHit* hit) const {
    ThreadWork() += renderer_work::kIntersect;
    return geometry->Intersect(r, kInfinity, hit);
  }
  bool Occluded(Vec3f p0, Vec3f p1) const {
    ThreadWork() += renderer_work::kOccluded;
    return geometry->Occluded(p0, p1);
  }
  float Transmittance(Vec3f p0, Vec3f p1) const { return medium.Transmittance(p0, p1); }
  // Visibility times transmittance.
  float Connect(Vec3f p0, Vec3f p1) const { return Occluded(p0, p1) ? 0.f : medium.Transmittance(p0, p1); }
};

}  // namespace vrlis::integration
