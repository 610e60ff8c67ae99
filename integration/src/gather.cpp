#include "vrlis_integration/gather.hpp"

#include <vrlis/gather/medium_gather.hpp>
#include <vrlis/gather/point_light_gather.hpp>
#include <vrlis/gather/surface_gather.hpp>

namespace vrli {
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

// The sum over the VRLs [first, last): the samplers are chosen and the camera segment and
// medium validated once for all of them, and the valid VRLs go to the library in batches
// (its step one runs a batch as vector lanes).
Spectrum GatherEach(vrlis::GatherMethod method, const Scene& scene, const CameraSegment& seg, const Vrl* first,
                    const Vrl* last, Rng& rng, QueryLog* log, Spectrum throughput) {
  const vrlis::RaySegment<float> camera = SegmentOf(seg);
  const vrlis::Medium<float> medium = MediumOf(scene.medium);
  const bool valid = vrlis::Validate(camera) == vrlis::QueryError::None &&
                     vrlis::Validate(medium) == vrlis::QueryError::None;
  return vrlis::WithGatherSamplers<float>(method, [&](auto step_one, auto step_two) {
    using StepOne = typename decltype(step_one)::type;
    using StepTwo = typename decltype(step_two)::type;
    constexpr int kBatch = vrlis::kVrlPointBatch;
    Spectrum sum;
    for (const Vrl* chunk = first; chunk < last; chunk += kBatch) {
      vrlis::VrlSegment<float> vrls[kBatch];
      float u_vrl[kBatch], u_camera[kBatch];
      const Vrl* source[kBatch];
      int count = 0;
      for (const Vrl* vrl = chunk; vrl != std::min(chunk + kBatch, last); ++vrl) {
        float u1 = rng.Uniform(), u2 = rng.Uniform();  // drawn for every VRL: images do not depend on batching
        vrlis::VrlSegment<float> segment = SegmentOf(*vrl);
        if (log) log->Record({camera, segment, medium}, RmsRgb(throughput * vrl->flux));
        if (!valid || vrlis::Validate(segment) != vrlis::QueryError::None) continue;
        vrls[count] = segment;
        u_vrl[count] = u1;
        u_camera[count] = u2;
        source[count++] = vrl;
      }
      vrlis::GatherSample<float> samples[kBatch];
      vrlis::SampleMediumGathers<StepOne, StepTwo>(vrlis::ValidQuery{}, camera, medium, vrls, count, u_vrl, u_camera,
                                                   samples);
      for (int i = 0; i < count; ++i) sum += source[i]->flux * Connect(scene, samples[i]);
    }
    return sum;
  });
}

}  // namespace

Spectrum GatherMediumToMedium(vrlis::GatherMethod method, const Scene& scene, const CameraSegment& seg,
                              const Vrl& vrl, Rng& rng, QueryLog* log, Spectrum throughput) {
  return GatherEach(method, scene, seg, &vrl, &vrl + 1, rng, log, throughput);
}

Spectrum GatherMediumToMedium(vrlis::GatherMethod method, const Scene& scene, const CameraSegment& seg,
                              const std::vector<Vrl>& vrls, Rng& rng, QueryLog* log, Spectrum throughput) {
  return GatherEach(method, scene, seg, vrls.data(), vrls.data() + vrls.size(), rng, log, throughput);
}

Spectrum GatherMediumToSurface(vrlis::Method method, const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo,
                               const std::vector<Vrl>& vrls, Rng& rng) {
  const vrlis::Medium<float> medium = MediumOf(scene.medium);
  const bool valid = vrlis::ValidateSurfacePoint(p, nf) == vrlis::QueryError::None &&
                     vrlis::Validate(medium) == vrlis::QueryError::None;
  return vrlis::CameraSamplers::WithEntry(method, [&](auto entry) {
    using Sampler = typename decltype(entry)::template Sampler<float>;
    constexpr int kBatch = vrlis::kVrlPointBatch;
    Spectrum sum;
    for (std::size_t chunk = 0; chunk < vrls.size(); chunk += kBatch) {
      vrlis::VrlSegment<float> segments[kBatch];
      float u[kBatch];
      const Vrl* source[kBatch];
      int count = 0;
      for (std::size_t i = chunk; i < std::min(chunk + kBatch, vrls.size()); ++i) {
        float ui = rng.Uniform();  // drawn for every VRL: images do not depend on batching
        vrlis::VrlSegment<float> segment = SegmentOf(vrls[i]);
        if (!valid || vrlis::Validate(segment) != vrlis::QueryError::None) continue;
        segments[count] = segment;
        u[count] = ui;
        source[count++] = &vrls[i];
      }
      vrlis::GatherSample<float> samples[kBatch];
      vrlis::SampleSurfaceGathers<Sampler>(vrlis::ValidQuery{}, p, nf, medium, segments, count, u, samples);
      for (int i = 0; i < count; ++i) sum += source[i]->flux * Connect(scene, samples[i]);
    }
    return albedo * sum;
  });
}

Spectrum SingleScattering(vrlis::Method method, const Scene& scene, const CameraSegment& seg, Rng& rng) {
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

}  // namespace vrli
