#pragma once
// A homogeneous medium with a Henyey-Greenstein phase function, filling all of space, an
// axis-aligned box or a sphere (the shapes the scenes need; all convex, so a ray meets the
// medium in one interval).
#include "common.hpp"

namespace vrlis::integration {

struct Interval {
  float a = 0, b = 0;
  bool Empty() const { return !(b > a); }
  float Length() const { return Empty() ? 0.f : b - a; }
};

struct HomogeneousMedium {
  float sigma_s = 0, sigma_a = 0, g = 0;
  enum class Shape { Everywhere, Box, Sphere } shape = Shape::Everywhere;
  Vec3f lo{}, hi{};       // the box
  Vec3f center{};         // the sphere
  float radius = 0;
  // Where an unbounded medium meets no surface, rays end here (transmittance e^-30 or so):
  // both the VRL renderer and its references use the same truncation.
  float max_distance = kInfinity;

  float SigmaT() const { return sigma_s + sigma_a; }
  float Albedo() const { return SigmaT() > 0 ? sigma_s / SigmaT() : 0.f; }
  bool Present() const { return sigma_s > 0 || sigma_a > 0; }
  bool Bounded() const { return shape != Shape::Everywhere; }
  bool Contains(Vec3f p) const {
    if (!Present()) return false;
    switch (shape) {
      case Shape::Everywhere: return true;
      case Shape::Box: return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
      case Shape::Sphere: return Dot(p - center, p - center) <= radius * radius;
    }
    return false;
  }

  // The part of the ray's [0, tmax] inside the medium.
  Interval Clip(const Ray& ray, float tmax) const {
    if (!Present()) return {};
    Interval iv{0, std::min(tmax, max_distance)};
    if (shape == Shape::Everywhere) return iv;
    if (shape == Shape::Sphere) {  // ray.d is a unit vector
      Vec3f oc = ray.o - center;
      float b = Dot(oc, ray.d), disc = b * b - (Dot(oc, oc) - radius * radius);
      if (!(disc > 0)) return {};
      float root = std::sqrt(disc);
      iv.a = std::max(iv.a, -b - root);
      iv.b = std::min(iv.b, -b + root);
      return iv;
    }
    const float o[3] = {ray.o.x, ray.o.y, ray.o.z}, d[3] = {ray.d.x, ray.d.y, ray.d.z};
    const float l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
    for (int k = 0; k < 3; ++k) {
      float inv = 1 / d[k];
      float t0 = (l[k] - o[k]) * inv, t1 = (h[k] - o[k]) * inv;
      if (t0 > t1) std::swap(t0, t1);
      if (std::isnan(t0)) return {};  // parallel ray exactly on a slab plane
      iv.a = std::max(iv.a, t0);
      iv.b = std::min(iv.b, t1);
    }
    return iv;
  }

  // Transmittance along the straight segment p0 -> p1.
  float Transmittance(Vec3f p0, Vec3f p1) const {
    Vec3f d = p1 - p0;
    float len = Length(d);
    if (!(len > 0)) return 1;
    return std::exp(-SigmaT() * Clip({p0, (1 / len) * d}, len).Length());
  }
};

}  // namespace vrlis::integration
