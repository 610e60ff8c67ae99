#pragma once
// The pipeline's Geometry implemented with Embree 3: quads, and spheres as a user geometry
// (an analytic test, which traces in about half the time of Embree's sphere points).
#include <embree3/rtcore.h>

#include <vector>

#include <vrlis_integration/scene.hpp>

namespace vrlis::scenes {

class EmbreeGeometry : public vrlis::integration::Geometry {
 public:
  EmbreeGeometry();
  ~EmbreeGeometry() override;
  EmbreeGeometry(const EmbreeGeometry&) = delete;
  EmbreeGeometry& operator=(const EmbreeGeometry&) = delete;

  // Corners in order around the quad.
  void AddQuad(vrlis::integration::Vec3f a, vrlis::integration::Vec3f b, vrlis::integration::Vec3f c, vrlis::integration::Vec3f d, int material);
  // The six faces of an axis-aligned box.
  void AddBox(vrlis::integration::Vec3f lo, vrlis::integration::Vec3f hi, int material);
  void AddSphere(vrlis::integration::Vec3f center, float radius, int material);
  void Commit();  // after the last Add
  bool Empty() const { return quad_vertices_.empty() && spheres_.empty(); }

  bool Intersect(const vrlis::integration::Ray& ray, float tmax, vrlis::integration::SurfaceHit* hit) const override;
  bool Occluded(vrlis::integration::Vec3f p0, vrlis::integration::Vec3f p1) const override;

  struct Sphere {
    vrlis::integration::Vec3f center;
    float radius;
    int material;
  };

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<vrlis::integration::Vec3f> quad_vertices_;
  std::vector<int> quad_materials_;
  std::vector<Sphere> spheres_;
  unsigned quad_geometry_ = RTC_INVALID_GEOMETRY_ID;
};

}  // namespace vrlis::scenes
