#pragma once
// A homogeneous medium with a Henyey-Greenstein phase function, filling either all of
// space or an axis-aligned box (the only shapes the scenes need; both are convex, so a ray
// meets the medium in one interval).
#include "common.hpp"

namespace vrlis::integration {

struct Interval {
  float a = 0, b = 0;
  bool Empty() const { return !(b > a); }
  float Length() const { return Empty() ? 0.f : b - a; }
};

struct HomogeneousMedium {
  float sigma_s = 0, sigma_a = 0, g = 0;
  bool bounded = false;   // false: the medium is everywhere
  Vec3f lo{}, hi{};       // the box when bounded
  // Where an unbounded medium meets no surface, rays end here (transmittance e^-30 or so):
  // both the VRL renderer and its references use the same truncation.
  float max_distance = kInfinity;

  float SigmaT() const { return sigma_s + sigma_a; }
  float Albedo() const { return SigmaT() > 0 ? sigma_s / SigmaT() : 0.f; }
  bool Present() const { return sigma_s > 0 || sigma_a > 0; }
  bool Contains(Vec3f p) const {
    if (!Present()) return false;
    return !bounded || (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z);
  }

  // The part of the ray's [0, tmax] inside the medium.
  Interval Clip(const Ray& ray, float tmax) const {
    if (!Present()) return {};
    Interval iv{0, std::min(tmax, max_distance)};
    if (!bounded) return iv;
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
