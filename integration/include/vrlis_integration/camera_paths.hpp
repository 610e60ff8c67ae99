#pragma once
// The camera pass of the VRL renderer: one camera path per pixel sample, following the
// specular chain from the camera to its first diffuse or medium vertex, gathering every
// VRL on the way (docs/renderer.md describes the decomposition).
#include <cstdint>
#include <vector>

#include <vrlis/method.hpp>

#include "effort_price.hpp"
#include "scene.hpp"
#include "transport.hpp"
#include "vpl.hpp"
#include "vrl.hpp"

namespace vrlis::integration {

struct GatherCount {
  std::uint64_t medium_to_medium = 0, medium_to_surface = 0;
  EffortStats medium_effort, surface_effort;  // with the effort control on only
  RemainderStats remainder;                   // with the effort control on only
  std::uint64_t Total() const { return medium_to_medium + medium_to_surface; }
};

// The transport's effort control with the pass's prices of the two gathers. `vpls` are the
// pass's VPLs: with the transport's vpl_bound above 0 they share the connections to diffuse
// points with the remainder whether or not the pass has any.
// `remainder_rate`: the remainder's paths per camera vertex, on average (stochastically
// rounded, each weighted 1 / rate; 1: one path, no number drawn).
Spectrum VrlRadiance(const Scene& scene, const TransportSettings& transport, const std::vector<Vrl>& vrls,
                     const VplSet& vpls, Ray ray,
                     Rng& rng, GatherCount* count, const vrlis::EffortSettings& medium_effort = {},
                     const vrlis::EffortSettings& surface_effort = {}, double remainder_rate = 1);

}  // namespace vrlis::integration
