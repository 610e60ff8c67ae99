#pragma once
// Virtual point lights (Keller 1997) at the light paths' diffuse vertices, gathered where a
// camera path would otherwise reach a diffuse point by path tracing: at the diffuse point
// ending the camera chain (surface to surface) and along every camera segment in the medium
// (surface to medium). The remainder, which reaches the same diffuse points by cosine or
// phase sampling, shares those connections (share.hpp): the VPL takes each up to the bound,
// the remainder the excess, and the remainder stops at every vertex a VPL covers whole. A
// gather connects a few VPLs chosen in proportion to their flux, not all of them (a pass may
// have hundreds), as many as the effort control's price asks where it is on
// (docs/maths.md#effort-split). docs/renderer.md has the decomposition.
#include <algorithm>
#include <utility>
#include <vector>

#include <vrlis/effort/policy.hpp>
#include <vrlis/effort/record.hpp>
#include <vrlis/method.hpp>

#include "alias_table.hpp"
#include "common.hpp"
#include "gather.hpp"
#include "scene.hpp"
#include "share.hpp"
#include "work.hpp"

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

// How many VPLs a gather connects: EffortSamples(rate) (floor(rate + u)), each weighted
// 1 / rate, so the gather keeps its mean whatever the rate (an integer rate: that many). With
// `record` set it adds the gather as a launch (SplitRecord, with the connections' variance
// within it in the pixel's units: beta is the camera path's throughput to the gather) and its
// counted work.
struct VplConnections {
  double rate = 1;
  Spectrum beta{1.f};
  vrlis::SplitRecord* record = nullptr;
};

// A gather's connections by `c`: connection() returns one's contribution before the gather's
// common factor `scale`; the sum comes back scaled and weighted 1 / rate. The record takes the
// sample variance of one connection's pixel contribution (scale and beta included) within the
// gather, zero contributions included, from gathers of two or more.
template <typename Connection>
Spectrum SplitConnections(const VplConnections& c, Spectrum scale, Rng& rng, Connection&& connection) {
  WorkScope scope(c.record ? &c.record->work : nullptr);
  const int n = vrlis::EffortSamples(c.rate, rng.Uniform());
  const Spectrum pixel = scale * c.beta;
  Spectrum sum;
  double squares = 0;
  for (int k = 0; k < n; ++k) {
    ThreadWork() += renderer_work::kConnect;  // its geometry term and transmittance; its ray counts itself
    const Spectrum y = connection();
    sum += y;
    squares += (y * pixel).MeanSquare();
  }
  if (c.record) {
    c.record->samples += n;
    if (n >= 2) {
      c.record->launches += 1;
      c.record->m2 += std::max(0.0, (squares - (sum * pixel).MeanSquare() / n) / (n - 1));
    }
  }
  return sum * scale * static_cast<float>(1 / c.rate);
}

// Radiance reflected towards the viewer by the diffuse point p (normal nf facing the viewer,
// albedo) from the VPLs, each connection's geometry term clamped at `bound`.
Spectrum GatherVpls(const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo, const VplSet& vpls,
                    const VplConnections& connections, float bound, Rng& rng);

// Radiance along the camera segment from the VPLs' light scattered once on it: a point on the
// segment for each VPL by `method` (the library's surface gather with the segment as its
// line), each sample's geometry term clamped at `bound`.
Spectrum GatherVpls(vrlis::SegmentChoice method, const Scene& scene, const CameraSegment& seg, const VplSet& vpls,
                    const VplConnections& connections, float bound, Rng& rng);

}  // namespace vrlis::integration
