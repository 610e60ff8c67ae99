#include "embree_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vrlis::scenes {

using vrlis::integration::Vec3f;

namespace {

using Sphere = EmbreeGeometry::Sphere;

// Ray parameters of a ray's entry into and exit from a sphere, t0 <= t1, or false if the ray
// misses it. The discriminant and roots are taken in the forms that do not cancel (Haines
// et al., "Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019).
bool SphereRoots(const Sphere& s, Vec3f o, Vec3f d, float* t0, float* t1) {
  Vec3f f = o - s.center;
  float a = vrlis::integration::Dot(d, d), b = -vrlis::integration::Dot(f, d);
  Vec3f l = f + (b / a) * d;  // f less its component along d
  float disc = s.radius * s.radius - vrlis::integration::Dot(l, l);
  if (!(disc >= 0)) return false;
  float c = vrlis::integration::Dot(f, f) - s.radius * s.radius;
  float q = b + std::copysign(std::sqrt(a * disc), b);
  *t0 = c / q;
  *t1 = q / a;
  if (*t0 > *t1) std::swap(*t0, *t1);
  return true;
}

// Ray i of a set of n rays that Embree hands to a user geometry.
Vec3f OriginOf(RTCRayN* rays, unsigned n, unsigned i) {
  return {RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)};
}
Vec3f DirectionOf(RTCRayN* rays, unsigned n, unsigned i) {
  return {RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i)};
}

// The first root along ray i that lies in its (tnear, tfar), if any.
bool FirstRootInside(const Sphere& s, RTCRayN* rays, unsigned n, unsigned i, float* t) {
  float t0, t1;
  if (!SphereRoots(s, OriginOf(rays, n, i), DirectionOf(rays, n, i), &t0, &t1)) return false;
  float tnear = RTCRayN_tnear(rays, n, i);
  *t = t0 > tnear ? t0 : t1;
  return *t > tnear && *t < RTCRayN_tfar(rays, n, i);
}

void SphereBounds(const RTCBoundsFunctionArguments* args) {
  const Sphere& s = static_cast<const Sphere*>(args->geometryUserPtr)[args->primID];
  *args->bounds_o = {s.center.x - s.radius, s.center.y - s.radius, s.center.z - s.radius, 0,
                     s.center.x + s.radius, s.center.y + s.radius, s.center.z + s.radius, 0};
}

void SphereIntersect(const RTCIntersectFunctionNArguments* args) {
  const Sphere& s = static_cast<const Sphere*>(args->geometryUserPtr)[args->primID];
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i) {
    float t;
    if (!args->valid[i] || !FirstRootInside(s, rays, args->N, i, &t)) continue;
    RTCRayN_tfar(rays, args->N, i) = t;
    Vec3f n = OriginOf(rays, args->N, i) + t * DirectionOf(rays, args->N, i) - s.center;
    RTCHitN_Ng_x(hits, args->N, i) = n.x;
    RTCHitN_Ng_y(hits, args->N, i) = n.y;
    RTCHitN_Ng_z(hits, args->N, i) = n.z;
    RTCHitN_u(hits, args->N, i) = RTCHitN_v(hits, args->N, i) = 0;
    RTCHitN_primID(hits, args->N, i) = args->primID;
    RTCHitN_geomID(hits, args->N, i) = args->geomID;
    RTCHitN_instID(hits, args->N, i, 0) = args->context->instID[0];
  }
}

void SphereOccluded(const RTCOccludedFunctionNArguments* args) {
  const Sphere& s = static_cast<const Sphere*>(args->geometryUserPtr)[args->primID];
  for (unsigned i = 0; i < args->N; ++i) {
    float t;
    if (args->valid[i] && FirstRootInside(s, args->ray, args->N, i, &t))
      RTCRayN_tfar(args->ray, args->N, i) = -std::numeric_limits<float>::infinity();
  }
}

}  // namespace

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
  if (!spheres_.empty()) {
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(spheres_.size()));
    rtcSetGeometryUserData(g, spheres_.data());
    rtcSetGeometryBoundsFunction(g, SphereBounds, nullptr);
    rtcSetGeometryIntersectFunction(g, SphereIntersect);
    rtcSetGeometryOccludedFunction(g, SphereOccluded);
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene_, g);  // primitive i is spheres_[i]; Intersect tells it from the quads by geomID
    rtcReleaseGeometry(g);
  }
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcCommitScene(scene_);
}

bool EmbreeGeometry::Intersect(const vrlis::integration::Ray& ray, float tmax, vrlis::integration::SurfaceHit* hit) const {
  if (Empty()) return false;  // a medium alone: no call into Embree per ray
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray.org_x = ray.o.x;
  rh.ray.org_y = ray.o.y;
  rh.ray.org_z = ray.o.z;
  rh.ray.dir_x = ray.d.x;
  rh.ray.dir_y = ray.d.y;
  rh.ray.dir_z = ray.d.z;
  rh.ray.tnear = vrlis::integration::kRayEpsilon;
  rh.ray.tfar = tmax;
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit->t = rh.ray.tfar;
  hit->p = ray(rh.ray.tfar);
  if (rh.hit.geomID == quad_geometry_) {
    hit->n = vrlis::integration::Normalize(Vec3f{rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z});
    hit->material = quad_materials_[rh.hit.primID];
  } else {
    const Sphere& s = spheres_[rh.hit.primID];
    hit->n = vrlis::integration::Normalize(hit->p - s.center);  // outwards
    hit->material = s.material;
  }
  return true;
}

bool EmbreeGeometry::Occluded(Vec3f p0, Vec3f p1) const {
  if (Empty()) return false;
  Vec3f d = p1 - p0;
  float len = vrlis::integration::Length(d);
  if (!(len > 2 * vrlis::integration::kRayEpsilon)) return false;
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
  ray.tnear = vrlis::integration::kRayEpsilon;
  ray.tfar = len - vrlis::integration::kRayEpsilon;
  ray.mask = ~0u;
  rtcOccluded1(scene_, &context, &ray);
  return ray.tfar < 0;
}

}  // namespace vrlis::scenes
