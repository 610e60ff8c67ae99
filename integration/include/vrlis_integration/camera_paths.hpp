#pragma once
// The camera pass of the VRL renderer: one camera path per pixel sample, following the
// specular chain from the camera to its first diffuse or medium vertex, gathering every
// VRL on the way (docs/renderer.md describes the decomposition).
#include <cstdint>
#include <vector>

#include <vrlis/effort/price.hpp>
#include <vrlis/method.hpp>

#include "gather.hpp"
#include "scene.hpp"
#include "transport.hpp"
#include "vpl.hpp"
#include "vrl.hpp"
#include "work.hpp"

namespace vrlis::integration {


// The remainder's paths from one camera vertex: EffortSamples(rate) of them (one, and no
// number drawn, at rate 1), each weighted 1 / rate, so the sum keeps its mean whatever the
// rate; `stats`, if set, adds what the price learns from (docs/maths.md#effort-split),
// its counted work included. `path` returns one path's contribution.
template <typename Path>
Spectrum SplitRemainder(double rate, Rng& rng, vrlis::SplitRecord* stats, Path&& path) {
  if (rate == 1 && !stats) return path();
  WorkScope scope(stats ? &stats->work : nullptr);
  const int n = rate == 1 ? 1 : vrlis::EffortSamples(rate, rng.Uniform());
  Spectrum sum;
  for (int i = 0; i < n; ++i) {
    const Spectrum y = path();
    if (stats) stats->m2 += y.MeanSquare() / rate;
    sum += y;
  }
  if (stats) stats->launches += 1, stats->samples += n;
  return sum * static_cast<float>(1 / rate);
}

// One camera path's VRL radiance. `gathers`: what its VRL gather calls take (gather.hpp); the
// effort's record, which must be set, counts their work and with the control on learns, the
// remainder's and the VPL connections' included (their samples per launch by
// effort.split_rate, stochastically rounded, each weighted 1 / rate). `vpls` are the pass's
// VPLs: with the transport's vpl_bound above 0 they share the connections to diffuse points
// with the remainder whether or not the pass has any.
Spectrum VrlRadiance(const Scene& scene, const TransportSettings& transport, const std::vector<Vrl>& vrls,
                     const VplSet& vpls, Ray ray, Rng& rng, const GatherOptions& gathers);

}  // namespace vrlis::integration
