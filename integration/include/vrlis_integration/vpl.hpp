#pragma once
// Virtual point lights (Keller 1997) at the light paths' diffuse vertices, gathered where a
// camera path would otherwise reach a diffuse point by path tracing: at the diffuse point
// ending the camera chain (surface to surface) and along every camera segment in the medium
// (surface to medium). The remainder, which reaches the same diffuse points by cosine or
// phase sampling, shares those connections (share.hpp): the VPL takes each up to the bound,
// the remainder the excess, and the remainder stops at every vertex a VPL covers whole. A
// gather connects a few VPLs chosen in proportion to their flux, not all of them (a pass may
// have hundreds). docs/renderer.md has the decomposition.
#include <utility>
#include <vector>

#include <vrlis/method.hpp>

#include "alias_table.hpp"
#include "common.hpp"
#include "gather.hpp"
#include "scene.hpp"
#include "share.hpp"

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
  bool empty() const { return choice_.empty(); }
  // The VPL for the uniform u in [0, 1) and the probability of choosing it.
  std::pair<const Vpl*, float> Sample(float u) const {
    const AliasTable::Pick pick = choice_.Sample(u);
    return {&vpls_[pick.index], pick.probability};
  }

 private:
  std::vector<Vpl> vpls_;
  AliasTable choice_;  // by flux: a gather takes several per shading point
};

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
