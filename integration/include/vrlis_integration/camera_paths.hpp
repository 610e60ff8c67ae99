#pragma once
// The camera pass of the VRL renderer: one camera path per pixel sample, following the
// specular chain from the camera to its first diffuse or medium vertex, gathering every
// VRL on the way (docs/renderer.md describes the decomposition).
#include <cstdint>
#include <vector>

#include <vrlis/effort/marginal_fits.hpp>
#include <vrlis/effort/policy.hpp>
#include <vrlis/method.hpp>

#include "effort_price.hpp"
#include "scene.hpp"
#include "transport.hpp"
#include "vpl.hpp"
#include "vrl.hpp"
#include "work.hpp"

namespace vrlis::integration {

struct GatherCount {
  std::uint64_t medium_to_medium = 0, medium_to_surface = 0;
  EffortStats medium_effort, surface_effort;  // with the effort control on only
  RemainderStats remainder;                   // with the effort control on only
  // If set, with VrlMarginal as step one: the medium-to-medium gathers' scores
  // (GatherMediumToMedium's marginal_scores).
  vrlis::ScoreOctaves* marginal_scores = nullptr;
  std::uint64_t Total() const { return medium_to_medium + medium_to_surface; }
};

// The remainder's paths from one camera vertex: EffortSamples(rate) of them (one, and no
// number drawn, at rate 1), each weighted 1 / rate, so the sum keeps its mean whatever the
// rate; `stats`, if set, adds what the price learns from (docs/maths.md#effort-remainder),
// its counted work included. `path` returns one path's contribution.
template <typename Path>
Spectrum SplitRemainder(double rate, Rng& rng, RemainderStats* stats, Path&& path) {
  if (rate == 1 && !stats) return path();
  WorkScope scope(stats ? &stats->work : nullptr);
  const int n = rate == 1 ? 1 : vrlis::EffortSamples(rate, rng.Uniform());
  Spectrum sum;
  for (int i = 0; i < n; ++i) {
    const Spectrum y = path();
    if (stats) stats->m2 += y.MeanSquare() / rate;
    sum += y;
  }
  if (stats) stats->launches += 1, stats->paths += n;
  return sum * static_cast<float>(1 / rate);
}

// The transport's effort control with the pass's prices of the two gathers. `vpls` are the
// pass's VPLs: with the transport's vpl_bound above 0 they share the connections to diffuse
// points with the remainder whether or not the pass has any.
// `remainder_rate`: the remainder's paths per camera vertex, on average (stochastically
// rounded, each weighted 1 / rate; 1: one path, no number drawn). `medium_pair`: the
// medium-to-medium gathers' statistics-only pair (GatherMediumToMedium).
Spectrum VrlRadiance(const Scene& scene, const TransportSettings& transport, const std::vector<Vrl>& vrls,
                     const VplSet& vpls, Ray ray,
                     Rng& rng, GatherCount* count, const vrlis::EffortSettings& medium_effort = {},
                     const vrlis::EffortSettings& surface_effort = {}, double remainder_rate = 1,
                     const vrlis::EffortSettings* medium_pair = nullptr);

}  // namespace vrlis::integration
