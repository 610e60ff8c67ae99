#include "vrlis_integration/gather.hpp"

#include <vrlis/gather/medium_gather.hpp>
#include <vrlis/gather/point_light_gather.hpp>
#include <vrlis/gather/surface_gather.hpp>

namespace vrlis::integration {
namespace {

vrlis::Medium<float> MediumOf(const HomogeneousMedium& m) { return {m.g, m.sigma_s, m.SigmaT()}; }
vrlis::RaySegment<float> SegmentOf(const CameraSegment& seg) { return {seg.ray.o, seg.ray.d, seg.iv.a, seg.iv.b}; }
vrlis::VrlSegment<float> SegmentOf(const Vrl& vrl) { return {vrl.origin, vrl.dir, vrl.length}; }

// The library's weight models the connection's transmittance in a medium that fills it;
// a bounded medium may not, and then the scene's own transmittance replaces it.
float Connect(const Scene& scene, Vec3f a, Vec3f b, float weight, float transmittance) {
  if (!(weight > 0) || scene.geometry->Occluded(a, b)) return 0;
  if (!scene.medium.bounded) return weight;
  return weight * (scene.Transmittance(a, b) / transmittance);
}
float Connect(const Scene& scene, const vrlis::GatherSample<float>& s) {
  return Connect(scene, s.camera_point, s.light_point, s.weight, s.transmittance);
}

float RmsRgb(Spectrum s) { return std::sqrt((s.r * s.r + s.g * s.g + s.b * s.b) / 3); }

}  // namespace

Spectrum MediumToMediumIntegrand(const Scene& scene, const CameraSegment& seg, const Vrl& vrl, float v, float t) {
  vrlis::MediumGatherQuery<float> q{SegmentOf(seg), SegmentOf(vrl), MediumOf(scene.medium)};
  float transmittance = 0;
  float f = vrlis::MediumGatherIntegrand(q, t, v, &transmittance);
  return vrl.flux * Connect(scene, seg.ray(t), vrl.origin + v * vrl.dir, f, transmittance);
}

namespace {

// A batch of VRLs for one of the library's batched gathers: the valid ones, their random
// numbers (u[k][i]: the k-th of VRL i) and the VRLs they came from.
template <int kUniforms>
struct VrlBatch {
  static constexpr int kSize = vrlis::kVrlPointBatch;
  vrlis::VrlSegment<float> segments[kSize];
  float u[kUniforms][kSize];
  const Vrl* source[kSize];
  int count = 0;
};

// sum flux * Connect over the VRLs [first, last), a batch at a time: gather(batch, samples)
// samples the batch; on_vrl(segment, vrl) sees every VRL, valid or not. kUniforms random
// numbers are drawn for every VRL, so images do not depend on batching or validity.
template <int kUniforms, typename OnVrl, typename Gather>
Spectrum SumOverBatches(const Scene& scene, const Vrl* first, const Vrl* last, bool valid, Rng& rng, OnVrl&& on_vrl,
                        Gather&& gather) {
  using Batch = VrlBatch<kUniforms>;
  Spectrum sum;
  for (std::ptrdiff_t begin = 0; begin < last - first; begin += Batch::kSize) {
    Batch batch;
    for (const Vrl* vrl = first + begin; vrl != first + std::min(begin + Batch::kSize, last - first); ++vrl) {
      float u[kUniforms];
      for (float& x : u) x = rng.Uniform();
      vrlis::VrlSegment<float> segment = SegmentOf(*vrl);
      on_vrl(segment, *vrl);
      if (!valid || vrlis::Validate(segment) != vrlis::QueryError::None) continue;
      batch.segments[batch.count] = segment;
      for (int k = 0; k < kUniforms; ++k) batch.u[k][batch.count] = u[k];
      batch.source[batch.count++] = vrl;
    }
    vrlis::GatherSample<float> samples[Batch::kSize];
    gather(batch, samples);
    for (int i = 0; i < batch.count; ++i) sum += batch.source[i]->flux * Connect(scene, samples[i]);
  }
  return sum;
}

// The medium-to-medium sum over the VRLs [first, last): the samplers are chosen and the
// camera segment and medium validated once for all of them.
Spectrum GatherEach(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg, const Vrl* first,
                    const Vrl* last, Rng& rng, QueryLog* log, Spectrum throughput) {
  const vrlis::RaySegment<float> camera = SegmentOf(seg);
  const vrlis::Medium<float> medium = MediumOf(scene.medium);
  const bool valid = vrlis::Validate(camera) == vrlis::QueryError::None &&
                     vrlis::Validate(medium) == vrlis::QueryError::None;
  return vrlis::WithGatherSamplers<float>(method, [&](auto step_one, auto step_two) {
    using StepOne = typename decltype(step_one)::type;
    using StepTwo = typename decltype(step_two)::type;
    return SumOverBatches<2>(
        scene, first, last, valid, rng,
        [&](const vrlis::VrlSegment<float>& segment, const Vrl& vrl) {
          if (log) log->Record({camera, segment, medium}, RmsRgb(throughput * vrl.flux));
        },
        [&](const VrlBatch<2>& b, vrlis::GatherSample<float>* samples) {
          vrlis::SampleMediumGathers<StepOne, StepTwo>(vrlis::ValidQuery{}, camera, medium, b.segments, b.count, b.u[0],
                                                       b.u[1], samples);
        });
  });
}

}  // namespace

Spectrum GatherMediumToMedium(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg,
                              const Vrl& vrl, Rng& rng, QueryLog* log, Spectrum throughput) {
  return GatherEach(method, scene, seg, &vrl, &vrl + 1, rng, log, throughput);
}

Spectrum GatherMediumToMedium(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg,
                              const std::vector<Vrl>& vrls, Rng& rng, QueryLog* log, Spectrum throughput) {
  return GatherEach(method, scene, seg, vrls.data(), vrls.data() + vrls.size(), rng, log, throughput);
}

Spectrum GatherMediumToSurface(vrlis::SegmentChoice method, const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo,
                               const std::vector<Vrl>& vrls, Rng& rng) {
  const vrlis::Medium<float> medium = MediumOf(scene.medium);
  const bool valid = vrlis::ValidateSurfacePoint(p, nf) == vrlis::QueryError::None &&
                     vrlis::Validate(medium) == vrlis::QueryError::None;
  return albedo * vrlis::SegmentSamplers::WithEntry(method, [&](auto entry) {
    using Sampler = typename decltype(entry)::template Sampler<float>;
    return SumOverBatches<1>(
        scene, vrls.data(), vrls.data() + vrls.size(), valid, rng, [](const vrlis::VrlSegment<float>&, const Vrl&) {},
        [&](const VrlBatch<1>& b, vrlis::GatherSample<float>* samples) {
          vrlis::SampleSurfaceGathers<Sampler>(vrlis::ValidQuery{}, p, nf, medium, b.segments, b.count, b.u[0], samples);
        });
  });
}

Spectrum SingleScattering(vrlis::SegmentChoice method, const Scene& scene, const CameraSegment& seg, Rng& rng) {
  const HomogeneousMedium& m = scene.medium;
  Spectrum sum;
  for (const PointLight& l : scene.lights.points) {
    if (l.fibonacci_beams) continue;  // delta directions: a camera ray never meets a beam
    vrlis::PointLightGatherQuery<float> q{SegmentOf(seg), l.position, MediumOf(m)};
    sum += l.intensity * Connect(scene, vrlis::SamplePointLightGather(method, q, rng.Uniform()));
  }
  if (!scene.lights.rects.empty() && std::isfinite(seg.iv.b)) {
    // Collimated beams: one distance, uniform on the segment, shared by all of them.
    float u = seg.iv.a + rng.Uniform() * seg.iv.Length();
    Vec3f x = seg.ray(u);
    float w = m.sigma_s * std::exp(-m.SigmaT() * (u - seg.iv.a)) * seg.iv.Length();
    for (const CollimatedRect& l : scene.lights.rects) {
      std::optional<LightSample> ls = SampleLight(l, x);
      if (!ls) continue;
      float tr = scene.Connect(x, ls->source);
      if (tr > 0) sum += ls->value * (w * Phase(m.g, Dot(ls->wi, seg.ray.d)) * tr);
    }
  }
  return sum;
}

}  // namespace vrlis::integration
