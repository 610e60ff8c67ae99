#pragma once
// Virtual point lights (Keller 1997) at the light paths' diffuse vertices, gathered where a
// camera path would otherwise reach a diffuse point by path tracing: at the diffuse point
// ending the camera chain (surface to surface) and along every camera segment in the medium
// (surface to medium). The remainder, which reaches the same diffuse points by cosine or
// phase sampling, shares those connections by Kollig and Keller's bias compensation (2004):
// a connection whose geometry term G (cos cos / r^2; at a medium point without its cosine)
// exceeds the bound b is taken by the VPL at b, and the remainder carries the excess with the
// weight 1 - b / G. The two weights add to one for every path, so the sum stays unbiased; the
// VPL's weight is bounded where it would be singular, and the remainder stops at every vertex
// a VPL covers whole. A gather connects a few VPLs chosen in proportion to their flux, not
// all of them (a pass may have hundreds). docs/renderer.md has the decomposition.
#include <utility>
#include <vector>

#include <vrlis/method.hpp>

#include "common.hpp"
#include "gather.hpp"
#include "scene.hpp"

namespace vrlis::integration {

struct Vpl {
  Vec3f p{}, n{};   // n: the unit normal on the side the light arrived from
  Spectrum flux{};  // the light path's flux arriving at p times the surface's albedo
};

// A pass's VPLs, chosen in proportion to their flux (the channels' mean).
class VplSet {
 public:
  VplSet() = default;
  explicit VplSet(std::vector<Vpl> vpls);
  bool empty() const { return cdf_.empty(); }
  // The VPL for the uniform u in [0, 1) and the probability of choosing it.
  std::pair<const Vpl*, float> Sample(float u) const;

 private:
  std::vector<Vpl> vpls_;
  std::vector<double> cdf_;  // of the VPLs with positive flux, ending at 1
  std::vector<std::size_t> index_;
};

// Where a camera path leaves for a diffuse point that a VPL could be: a diffuse point (with
// its unit normal facing that way) or a medium point.
struct VplShareStart {
  Vec3f p{}, n{};
  bool surface = true;
};

// The geometry term between the start and the diffuse point b (unit normal nb on the side
// facing the start); 0 when either faces away.
inline float GeometryTerm(const VplShareStart& a, Vec3f b, Vec3f nb) {
  Vec3f w = b - a.p;
  float r2 = Dot(w, w);
  if (!(r2 > 0)) return 0;
  float r = std::sqrt(r2), cos_a = a.surface ? Dot(a.n, w) / r : 1, cos_b = -Dot(nb, w) / r;
  return cos_a > 0 && cos_b > 0 ? cos_a * cos_b / r2 : 0.f;
}

// The share of a connection of geometry term g that the remainder carries: 1 - b / g above
// the bound b, else none (b = 0: all of it, no VPLs).
inline float RemainderShare(float g, float bound) { return g > bound ? 1 - bound / g : 0.f; }

// Radiance reflected towards the viewer by the diffuse point p (normal nf facing the viewer,
// albedo) from the VPLs: `samples` connections, each connection's geometry term clamped at
// `bound`.
Spectrum GatherVpls(const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo, const VplSet& vpls, int samples,
                    float bound, Rng& rng);

// Radiance along the camera segment from the VPLs' light scattered once on it: `samples`
// VPLs, a point on the segment for each by `method` (the library's surface gather with the
// segment as its line), each sample's geometry term clamped at `bound`.
Spectrum GatherVpls(vrlis::SegmentChoice method, const Scene& scene, const CameraSegment& seg, const VplSet& vpls,
                    int samples, float bound, Rng& rng);

}  // namespace vrlis::integration
