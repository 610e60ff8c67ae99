#pragma once
// Virtual point lights (Keller 1997) at the light paths' diffuse vertices, gathered at the
// diffuse point that ends a camera chain, and the split of those surface-to-surface
// connections with the path-traced remainder that keeps the sum unbiased: Kollig and
// Keller's bias compensation (2004). A connection whose geometry term G = cos cos / r^2
// exceeds the bound b is taken by the VPL at b, and the remainder, which reaches the same
// vertex by cosine sampling, carries the excess with the weight 1 - b / G. The VPL's
// weight is then bounded where it would be singular (near corners), and the remainder
// stops at every vertex a VPL fully covers. docs/renderer.md has the decomposition.
#include <vector>

#include "common.hpp"
#include "scene.hpp"

namespace vrlis::integration {

struct Vpl {
  Vec3f p{}, n{};  // n: the unit normal on the side the light arrived from
  Spectrum flux{};  // the light path's flux arriving at p times the surface's albedo / pi
};

// The geometry term between diffuse points a and b with unit normals facing each other's side;
// 0 when either faces away.
inline float GeometryTerm(Vec3f a, Vec3f na, Vec3f b, Vec3f nb) {
  Vec3f w = b - a;
  float r2 = Dot(w, w);
  if (!(r2 > 0)) return 0;
  float cos_a = Dot(na, w), cos_b = -Dot(nb, w);
  return cos_a > 0 && cos_b > 0 ? cos_a * cos_b / (r2 * r2) : 0.f;
}

// The share of a connection of geometry term g that the remainder carries: 1 - b / g above
// the bound b, else none (b = 0: all of it, no VPLs).
inline float RemainderShare(float g, float bound) { return g > bound ? 1 - bound / g : 0.f; }

// Radiance reflected towards the viewer by the diffuse point p (normal nf facing the viewer,
// albedo) from every VPL, each connection's geometry term clamped at `bound`.
Spectrum GatherVpls(const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo, const std::vector<Vpl>& vpls, float bound);

}  // namespace vrlis::integration
