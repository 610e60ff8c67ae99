#pragma once
// The pipeline's Geometry implemented with Embree 3: quads, and spheres as a user geometry
// (an analytic test, which traces in about half the time of Embree's sphere points).
#include <embree3/rtcore.h>

#include <vector>

#include <vrlis_integration/scene.hpp>

namespace vrl_render {

class EmbreeGeometry : public vrli::Geometry {
 public:
  EmbreeGeometry();
  ~EmbreeGeometry() override;
  EmbreeGeometry(const EmbreeGeometry&) = delete;
  EmbreeGeometry& operator=(const EmbreeGeometry&) = delete;

  // Corners in order around the quad.
  void AddQuad(vrli::Vec3f a, vrli::Vec3f b, vrli::Vec3f c, vrli::Vec3f d, int material);
  // The six faces of an axis-aligned box.
  void AddBox(vrli::Vec3f lo, vrli::Vec3f hi, int material);
  void AddSphere(vrli::Vec3f center, float radius, int material);
  void Commit();  // after the last Add
  bool Empty() const { return quad_vertices_.empty() && spheres_.empty(); }

  bool Intersect(const vrli::Ray& ray, float tmax, vrli::SurfaceHit* hit) const override;
  bool Occluded(vrli::Vec3f p0, vrli::Vec3f p1) const override;

  struct Sphere {
    vrli::Vec3f center;
    float radius;
    int material;
  };

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<vrli::Vec3f> quad_vertices_;
  std::vector<int> quad_materials_;
  std::vector<Sphere> spheres_;
  unsigned quad_geometry_ = RTC_INVALID_GEOMETRY_ID;
};

}  // namespace vrl_render
