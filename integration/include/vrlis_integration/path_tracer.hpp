#pragma once
// A volumetric path tracer with next-event estimation: free-flight distance sampling,
// phase-function and cosine sampling, Russian roulette; in the medium, light scattered once
// on a segment is estimated along the whole segment by equiangular sampling, except that a
// point light inside the medium is gathered at the scattering vertex before the segment
// (VertexSingleScattering). It is the reference renderer, and the VRL renderer's `indirect`
// part continues paths with it.
#include "scene.hpp"
#include "transport.hpp"
#include "gather.hpp"
#include "share.hpp"

namespace vrlis::integration {

// Where the remainder leaves a camera vertex: the vertex as one end of its connections, and
// how it scatters (the light it gathers jointly with VertexSingleScattering).
struct RemainderStart {
  ConnectionEnd from;
  VertexLobe lobe;
};

class PathTracer {
 public:
  PathTracer(const Scene& scene, const TransportSettings& transport) : scene_(scene), tr_(transport) {}

  // Radiance arriving at ray.o along -ray.d. `depth` counts the interactions already on
  // the path. With `start`, ray.o is a camera vertex whose gathers took part of its
  // connections (share.hpp): the VRL gathers those to medium points up to the transport's
  // vrl_bound (kUnbounded: all of them, and the first segment only attenuates), the VPL
  // gathers those to diffuse points up to its vpl_bound; the path carries the rest.
  Spectrum Li(Ray ray, Rng& rng, int depth = 0, const RemainderStart* start = nullptr) const;

 private:
  const Scene& scene_;
  TransportSettings tr_;
};

}  // namespace vrlis::integration
