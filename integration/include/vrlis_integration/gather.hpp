#pragma once
// The VRL estimators of docs/maths.md#estimators, one sample each, as a renderer uses the
// library: build the query, let vrlis sample and weight it, trace one occlusion ray.
#include <vrlis/effort/price.hpp>
#include <vrlis/gather/gather_sample.hpp>
#include <vrlis/method.hpp>

#include <vector>

#include "query_log.hpp"
#include "scene.hpp"
#include "share.hpp"
#include "vrl.hpp"
#include "weight_log.hpp"

namespace vrlis::integration {

// The part of a camera ray inside the medium: x(u) = ray(u), u in [iv.a, iv.b]. The
// transmittance from x(u) back to the ray origin is exp(-sigma_t (u - iv.a)).
struct CameraSegment {
  Ray ray;
  Interval iv;
};

// The scene's homogeneous medium as the library's.
vrlis::Medium<float> MediumOf(const HomogeneousMedium& m);

// A gather sample's weight times the visibility of its two points, the connection's
// transmittance the scene's where the medium is bounded (the library's assumes it fills the
// connection): 0 for a sample that does not contribute.
float Connect(const Scene& scene, const vrlis::GatherSample<float>& s);

// What a VRL gather call of the camera pass takes besides its query: the pixel's effort
// (vrlis/effort/price.hpp; its settings with the control off too, e.g. VrlMarginal's
// threshold) and its record (none: nothing learned or counted), whether it also gathers its
// medium VRLs under the accurate model for the statistics (PixelEffort::Pair), where
// VrlMarginal's scores, the query log and the weight log go, and the geometry term up to
// which each sample's connection is taken (share.hpp; the remainder carries the rest).
struct GatherOptions {
  vrlis::PixelEffort effort;
  bool pair = false;
  vrlis::ScoreOctaves* marginal_scores = nullptr;
  QueryLog* query_log = nullptr;    // medium-to-medium: each query offered with weight throughput x flux
  WeightLog* weight_log = nullptr;  // every sample taken (weight_log.hpp)
  float bound = kUnbounded;
};

// Radiance along the camera ray from light scattered at a VRL point and again on the segment
// (the single-VRL form of the sum below, which the comparison uses per VRL).
Spectrum GatherMediumToMedium(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg,
                              const Vrl& vrl, Rng& rng);

// The sum of GatherMediumToMedium over every VRL, with the same random numbers in the same
// order: the camera pass's inner loop, one call of the library's GatherMediumVrls, each VRL's
// predicted contribution throughput x flux. A pair leaves the sum and the numbers the rest of
// the path draws as they are without it.
Spectrum GatherMediumToMedium(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg,
                              const std::vector<Vrl>& vrls, Rng& rng, Spectrum throughput,
                              const GatherOptions& options);

// The medium-to-medium integrand at VRL point v and camera point t (what the gather divides
// by its two pdfs): exposed so that the comparison can integrate either step by quadrature.
Spectrum MediumToMediumIntegrand(const Scene& scene, const CameraSegment& seg, const Vrl& vrl, float v, float t);

// Radiance reflected towards the camera by a diffuse point (normal nf facing the camera,
// albedo) from light scattered on every VRL, the VRL points by `method` (one uniform
// each): the sampler is chosen and the point and medium validated once for all the VRLs
// (the library's GatherSurfaceVrls; options as in GatherMediumToMedium, no pair).
Spectrum GatherMediumToSurface(vrlis::SegmentChoice method, const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo,
                               const std::vector<Vrl>& vrls, Rng& rng, Spectrum throughput,
                               const GatherOptions& options);

// Single scattering along the segment from every light (point lights: the camera point by
// `method`; collimated lights: uniform in distance on the part inside the beam). `after_vertex`: the segment leaves a
// scattering vertex that VertexSingleScattering already gathered at, so the point lights it
// covers are left out. With `share`, each sample weighs the remainder's share of its
// connection (the segment leaves a camera vertex whose VRL gathers took the rest).
Spectrum SingleScattering(vrlis::SegmentChoice method, const Scene& scene, const CameraSegment& seg, Rng& rng,
                          bool after_vertex = false, const MediumShare* share = nullptr);

// How a scattering vertex sends light on: the phase function about the direction of travel
// into a medium vertex, or the cosine about a diffuse point's normal (the albedo is the
// caller's), as densities over the directions leaving it.
struct VertexLobe {
  Vec3f axis{};
  float g = 0;
  bool cosine = false;
  float operator()(Vec3f w) const;
};

// Whether VertexSingleScattering covers this light: a point light inside the medium, next to
// which a ray sampled by the lobe and then a distance would keep a 1 / sin weight of
// unbounded variance (docs/maths.md#two-point).
bool GatheredAtVertex(const Scene& scene, const PointLight& light);

// Light of the point lights GatheredAtVertex covers, scattered once in the medium and then at
// the vertex p through `lobe`: the direction from p by vrlis::SampleTwoPointDirection, the
// distance on its medium segment by equiangular sampling about the light.
// `share` as in SingleScattering.
Spectrum VertexSingleScattering(const Scene& scene, Vec3f p, const VertexLobe& lobe, Rng& rng,
                                const MediumShare* share = nullptr);

}  // namespace vrlis::integration
