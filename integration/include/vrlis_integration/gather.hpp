#pragma once
// The VRL estimators of docs/maths.md#estimators, one sample each, as a renderer uses the
// library: build the query, let vrlis sample and weight it, trace one occlusion ray.
#include <vrlis/effort/marginal_fits.hpp>
#include <vrlis/effort/policy.hpp>
#include <vrlis/gather/gather_sample.hpp>
#include <vrlis/method.hpp>

#include <vector>

#include "effort_price.hpp"
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

// Radiance along the camera ray from light scattered at a VRL point and again on the segment
// (the single-VRL form of the sum below, which the comparison uses per VRL).
// With a log, the query is offered to it with the weight throughput x flux (query_log.hpp).
Spectrum GatherMediumToMedium(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg,
                              const Vrl& vrl, Rng& rng, QueryLog* log = nullptr, Spectrum throughput = Spectrum(1.f));

// The sum of GatherMediumToMedium over every VRL, with the same random numbers in the same
// order: the camera pass's inner loop, one call of the library's GatherMediumVrls. With the
// effort control (vrlis/effort/policy.hpp) each VRL is gathered q times on average, q from its
// predicted contribution throughput x flux; `stats`, if set, adds what the price learns from;
// `weight_log`, if set, records every sample taken (weight_log.hpp). Each sample's connection
// is taken up to the geometry term `bound` (share.hpp; the remainder carries the rest).
// `pair`, with stats: the same VRLs are also gathered under these settings, on the same
// random numbers, for the statistics alone, not the radiance (EffortStats::pair_delta).
// `marginal_scores`, if set and VrlMarginal is step one: the gathers' scores, from which the
// renderer learns EffortSettings::marginal_threshold.
Spectrum GatherMediumToMedium(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg,
                              const std::vector<Vrl>& vrls, Rng& rng, QueryLog* log = nullptr,
                              Spectrum throughput = Spectrum(1.f), const vrlis::EffortSettings& effort = {},
                              EffortStats* stats = nullptr, WeightLog* weight_log = nullptr,
                              float bound = kUnbounded, const vrlis::EffortSettings* pair = nullptr,
                              vrlis::ScoreOctaves* marginal_scores = nullptr);

// The medium-to-medium integrand at VRL point v and camera point t (what the gather divides
// by its two pdfs): exposed so that the comparison can integrate either step by quadrature.
Spectrum MediumToMediumIntegrand(const Scene& scene, const CameraSegment& seg, const Vrl& vrl, float v, float t);

// Radiance reflected towards the camera by a diffuse point (normal nf facing the camera,
// albedo) from light scattered on every VRL, the VRL points by `method` (one uniform
// each): the sampler is chosen and the point and medium validated once for all the VRLs
// (the library's GatherSurfaceVrls; effort, stats, weight_log and bound as in
// GatherMediumToMedium).
Spectrum GatherMediumToSurface(vrlis::SegmentChoice method, const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo,
                               const std::vector<Vrl>& vrls, Rng& rng, Spectrum throughput = Spectrum(1.f),
                               const vrlis::EffortSettings& effort = {}, EffortStats* stats = nullptr,
                               WeightLog* weight_log = nullptr, float bound = kUnbounded);

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
