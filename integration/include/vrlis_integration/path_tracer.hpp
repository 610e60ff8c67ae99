#pragma once
// A volumetric path tracer with next-event estimation: free-flight distance sampling,
// phase-function and cosine sampling, Russian roulette; in the medium, light scattered once
// on a segment is estimated along the whole segment by equiangular sampling, except that a
// point light inside the medium is gathered at the scattering vertex before the segment
// (VertexSingleScattering). It is the reference renderer, and the VRL renderer's `indirect`
// part continues paths with it.
#include "scene.hpp"
#include "transport.hpp"
#include "vpl.hpp"

namespace vrlis::integration {

class PathTracer {
 public:
  PathTracer(const Scene& scene, const TransportSettings& transport) : scene_(scene), tr_(transport) {}

  // Radiance arriving at ray.o along -ray.d. `depth` counts the interactions already on
  // the path; with `skip_first_medium` the first segment only attenuates (its medium
  // vertices are someone else's: the VRL gathers'). With `shared` set (and
  // `skip_first_medium`), ray.o is a point whose connections to diffuse points the VPL
  // gathers share up to the transport's vpl_bound: light from the first vertex, if diffuse,
  // weighs RemainderShare (vpl.hpp).
  Spectrum Li(Ray ray, Rng& rng, int depth = 0, bool skip_first_medium = false,
              const VplShareStart* shared = nullptr) const;

 private:
  const Scene& scene_;
  TransportSettings tr_;
};

}  // namespace vrlis::integration
