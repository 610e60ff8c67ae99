#pragma once
// Connections shared between a gather and the path-traced remainder: Kollig and Keller's bias
// compensation (2004), made exact. A gather (VPLs, VRLs) takes a connection of geometry term G
// up to the bound b, weight min(1, b / G); the remainder, which reaches the same vertex by
// sampling from the camera's side, carries the excess, weight 1 - b / G where G > b. The two
// weights add to one for every path, so the sum stays unbiased, and the gather's weight stays
// bounded where 1 / r^2 would make it singular (docs/renderer.md#vpls).
#include <cmath>
#include <limits>

#include "common.hpp"

namespace vrlis::integration {

// The bound at which a gather carries every connection whole: no sharing.
inline constexpr float kUnbounded = std::numeric_limits<float>::infinity();

// One end of a connection: a diffuse point (its unit normal facing the other end) or a medium
// point, which has no cosine.
struct ConnectionEnd {
  Vec3f p{}, n{};
  bool surface = false;
};

// cos_a cos_b / r^2 with each cosine only at a surface end; 0 when either faces away.
inline float GeometryTerm(const ConnectionEnd& a, const ConnectionEnd& b) {
  Vec3f w = b.p - a.p;
  float r2 = Dot(w, w);
  if (!(r2 > 0)) return 0;
  float r = std::sqrt(r2), cos_a = a.surface ? Dot(a.n, w) / r : 1, cos_b = b.surface ? -Dot(b.n, w) / r : 1;
  return cos_a > 0 && cos_b > 0 ? cos_a * cos_b / r2 : 0.f;
}

// The gather's share of a connection of geometry term g: min(1, b / g).
inline float GatherShare(float g, float bound) { return g > bound ? bound / g : 1.f; }

// The remainder's share: 1 - b / g above the bound, else none; all of it when b = 0 (no
// gather takes these connections).
inline float RemainderShare(float g, float bound) {
  if (!(bound > 0)) return 1;
  return g > bound ? 1 - bound / g : 0.f;
}

// The remainder's share of every connection from `from` to a medium point (bound kUnbounded:
// none, the VRL gathers carry them whole).
struct MediumShare {
  ConnectionEnd from;
  float bound = kUnbounded;
  float operator()(Vec3f y) const { return RemainderShare(GeometryTerm(from, {y, {}, false}), bound); }
};

}  // namespace vrlis::integration
