#include "embree_geometry.hpp"

#include <stdexcept>

namespace vrl_render {

using vrli::Vec3f;

EmbreeGeometry::EmbreeGeometry() {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error("cannot create an Embree device");
  scene_ = rtcNewScene(device_);
}

EmbreeGeometry::~EmbreeGeometry() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

void EmbreeGeometry::AddQuad(Vec3f a, Vec3f b, Vec3f c, Vec3f d, int material) {
  quad_vertices_.insert(quad_vertices_.end(), {a, b, c, d});
  quad_materials_.push_back(material);
}

void EmbreeGeometry::AddBox(Vec3f lo, Vec3f hi, int material) {
  auto corner = [&](int i) { return Vec3f{i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z}; };
  const int faces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  for (const auto& f : faces) AddQuad(corner(f[0]), corner(f[1]), corner(f[2]), corner(f[3]), material);
}

void EmbreeGeometry::AddSphere(Vec3f center, float radius, int material) {
  spheres_.push_back({center, radius, material});
}

void EmbreeGeometry::Commit() {
  if (!quad_materials_.empty()) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_QUAD);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), quad_vertices_.size()));
    for (std::size_t i = 0; i < quad_vertices_.size(); ++i) {
      v[3 * i] = quad_vertices_[i].x;
      v[3 * i + 1] = quad_vertices_[i].y;
      v[3 * i + 2] = quad_vertices_[i].z;
    }
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4,
                                                               4 * sizeof(unsigned), quad_materials_.size()));
    for (unsigned i = 0; i < 4 * quad_materials_.size(); ++i) idx[i] = i;
    rtcCommitGeometry(g);
    quad_geometry_ = rtcAttachGeometry(scene_, g);
    rtcReleaseGeometry(g);
  }
  for (std::size_t i = 0; i < spheres_.size(); ++i) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* v = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
    v[0] = spheres_[i].center.x;
    v[1] = spheres_[i].center.y;
    v[2] = spheres_[i].center.z;
    v[3] = spheres_[i].radius;
    rtcCommitGeometry(g);
    unsigned id = rtcAttachGeometry(scene_, g);
    rtcReleaseGeometry(g);
    if (sphere_of_geometry_.size() <= id) sphere_of_geometry_.resize(id + 1, -1);
    sphere_of_geometry_[id] = static_cast<int>(i);
  }
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcCommitScene(scene_);
}

bool EmbreeGeometry::Intersect(const vrli::Ray& ray, float tmax, vrli::SurfaceHit* hit) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = ray.o.x;
  rh.ray.org_y = ray.o.y;
  rh.ray.org_z = ray.o.z;
  rh.ray.dir_x = ray.d.x;
  rh.ray.dir_y = ray.d.y;
  rh.ray.dir_z = ray.d.z;
  rh.ray.tnear = vrli::kRayEpsilon;
  rh.ray.tfar = tmax;
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit->t = rh.ray.tfar;
  hit->p = ray(rh.ray.tfar);
  if (rh.hit.geomID == quad_geometry_) {
    hit->n = vrli::Normalize(Vec3f{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
    hit->material = quad_materials_[rh.hit.primID];
  } else {
    const Sphere& s = spheres_[static_cast<std::size_t>(sphere_of_geometry_[rh.hit.geomID])];
    hit->n = vrli::Normalize(hit->p - s.center);  // outwards
    hit->material = s.material;
  }
  return true;
}

bool EmbreeGeometry::Occluded(Vec3f p0, Vec3f p1) const {
  Vec3f d = p1 - p0;
  float len = vrli::Length(d);
  if (!(len > 2 * vrli::kRayEpsilon)) return false;
  d = (1 / len) * d;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray{};
  ray.org_x = p0.x;
  ray.org_y = p0.y;
  ray.org_z = p0.z;
  ray.dir_x = d.x;
  ray.dir_y = d.y;
  ray.dir_z = d.z;
  ray.tnear = vrli::kRayEpsilon;
  ray.tfar = len - vrli::kRayEpsilon;
  ray.mask = ~0u;
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar < 0;
}

}  // namespace vrl_render
