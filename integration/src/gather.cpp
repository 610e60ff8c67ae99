#include "vrlis_integration/gather.hpp"

#include <vrlis/core/two_point_direction.hpp>
#include <vrlis/gather/gather_instances.hpp>
#include <vrlis/gather/gather_vrls.hpp>
#include <vrlis/gather/medium_gather.hpp>
#include <vrlis/gather/point_light_gather.hpp>
#include <vrlis/samplers/equiangular.hpp>

#include "vrlis_integration/work.hpp"

// Every sampler pair's batches, compiled once into this library (integration/CMakeLists.txt).
VRLIS_EXTERN_GATHERS(float)

namespace vrlis::integration {

vrlis::Medium<float> MediumOf(const HomogeneousMedium& m) {
  return vrlis::Medium<float>::FromAbsorptionScattering(m.g, m.sigma_a, m.sigma_s);
}

namespace {

vrlis::RaySegment<float> SegmentOf(const CameraSegment& seg) { return {seg.ray.o, seg.ray.d, seg.iv.a, seg.iv.b}; }
vrlis::VrlSegment<float> SegmentOf(const Vrl& vrl) { return {vrl.origin, vrl.dir, vrl.length}; }

// The library's weight models the connection's transmittance in a medium that fills it;
// a bounded medium may not, and then the scene's own transmittance replaces it.
float Connect(const Scene& scene, Vec3f a, Vec3f b, float weight, float transmittance) {
  if (!(weight > 0) || scene.Occluded(a, b)) return 0;
  if (!scene.medium.Bounded()) return weight;
  return weight * (scene.Transmittance(a, b) / transmittance);
}

}  // namespace

float Connect(const Scene& scene, const vrlis::GatherSample<float>& s) {
  return Connect(scene, s.camera_point, s.light_point, s.weight, s.transmittance);
}

namespace {

// A point light's cone is the renderer's: the library's point light emits everywhere.
float Connect(const Scene& scene, const PointLight& light, const vrlis::GatherSample<float>& s) {
  return light.Lights(s.camera_point) ? Connect(scene, s) : 0.f;
}

}  // namespace

Spectrum MediumToMediumIntegrand(const Scene& scene, const CameraSegment& seg, const Vrl& vrl, float v, float t) {
  vrlis::MediumGatherQuery<float> q{SegmentOf(seg), SegmentOf(vrl), MediumOf(scene.medium)};
  float transmittance = 0;
  float f = vrlis::MediumGatherIntegrand(q, t, v, &transmittance);
  return vrl.flux * Connect(scene, seg.ray(t), vrl.origin + v * vrl.dir, f, transmittance);
}

namespace {

// The library's one-call gathers over VRLs [first, last), kChunk at a time (a multiple of
// the library's batch, so that images do not depend on it): segments and predicted weights
// on the stack, the scene's visibility as the visitor, which returns its contribution in the
// price's units (the RMS of the pixel's RGB). The calls count their work into the pixel's
// record, the visits at renderer_work's constants: the rays the visits trace are not
// counted again. gather_chunk(call, numbers, segments, n, visit) makes one call;
// reads(call, u) says whether it reads the segments and weights, u its first number
// (vrlis::MediumGatherReadsVrls): a chunk whose call does not is not built.
constexpr int kChunk = 8 * vrlis::kVrlPointBatch;

template <typename GatherShareOf, typename Reads, typename GatherChunk>
Spectrum SumOverChunks(const Scene& scene, const Vrl* first, const Vrl* last, Spectrum throughput,
                       const GatherOptions& options, bool surface, Rng& own, GatherShareOf&& share, Reads&& reads,
                       GatherChunk&& gather_chunk) {
  const vrlis::PixelEffort& effort = options.effort;
  const bool pair = options.pair && effort.record;
  Spectrum sum;
  for (const Vrl* chunk = first; chunk < last; chunk += kChunk) {
    const int n = static_cast<int>(std::min<std::ptrdiff_t>(kChunk, last - chunk));
    vrlis::VrlSegment<float> segments[kChunk];
    float weights[kChunk];  // for decided gathers, and VrlMarginal's choice of fits
    const vrlis::EffortCall<float> call = surface ? effort.Surface(weights) : effort.Medium(weights, options.marginal_scores);
    if (Rng peek = own; pair || reads(call, double(peek.Uniform())))
      for (int i = 0; i < n; ++i) segments[i] = SegmentOf(chunk[i]), weights[i] = (throughput * chunk[i].flux).Rms();
    // One visitor for the call and its pair (a second would compile every sampler pair again);
    // the pair's samples are measured, not summed.
    bool summed = true;
    auto visit = [&](int i, const vrlis::GatherSample<float>& s, float effort_weight) {
      const Spectrum x = chunk[i].flux * (Connect(scene, s) * share(s) * effort_weight);
      const float y = (throughput * x).Rms();
      if (!summed) return y;
      sum += x;
      if (options.weight_log) options.weight_log->Record(effort_weight, s.weight, y);
      return y;
    };
    Rng same = own;
    WorkScope uncounted(nullptr, false);  // the record counts the call's work
    gather_chunk(call, own, segments, n, visit);
    if (pair) {  // for the statistics alone, on the same numbers: its own are not the path's
      summed = false;
      gather_chunk(effort.Pair(weights), same, segments, n, visit);
      summed = true;
    }
  }
  return sum;
}

// The gather's share of a sample's connection from `from` to the VRL point (share.hpp).
float GatherShareOf(const ConnectionEnd& from, const vrlis::GatherSample<float>& s, float bound) {
  return bound < kUnbounded ? GatherShare(GeometryTerm(from, {s.light_point, {}, false}), bound) : 1.f;
}

// The medium-to-medium sum over the VRLs [first, last).
Spectrum GatherEach(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg, const Vrl* first,
                    const Vrl* last, Rng& rng, Spectrum throughput, const GatherOptions& options) {
  const vrlis::RaySegment<float> camera = SegmentOf(seg);
  const vrlis::Medium<float> medium = MediumOf(scene.medium);
  Rng own = rng.Split();
  if (options.query_log)
    for (const Vrl* vrl = first; vrl != last; ++vrl)
      options.query_log->Record({camera, SegmentOf(*vrl), medium}, (throughput * vrl->flux).Rms());
  auto share = [&](const vrlis::GatherSample<float>& s) {
    return GatherShareOf({s.camera_point, {}, false}, s, options.bound);
  };
  auto reads = [&](const vrlis::EffortCall<float>& call, double u) { return vrlis::MediumGatherReadsVrls(method, call, u); };
  return SumOverChunks(scene, first, last, throughput, options, false, own, share, reads,
                       [&](const vrlis::EffortCall<float>& call, Rng& numbers, const vrlis::VrlSegment<float>* segments,
                           int n, auto& visit) {
                         vrlis::GatherMediumVrls(method, camera, medium, segments, n, [&] { return numbers.Uniform(); },
                                                 visit, call);
                       });
}

}  // namespace

Spectrum GatherMediumToMedium(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg,
                              const std::vector<Vrl>& vrls, Rng& rng, Spectrum throughput,
                              const GatherOptions& options) {
  return GatherEach(method, scene, seg, vrls.data(), vrls.data() + vrls.size(), rng, throughput, options);
}

Spectrum GatherMediumToMedium(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg,
                              const Vrl& vrl, Rng& rng) {
  return GatherEach(method, scene, seg, &vrl, &vrl + 1, rng, Spectrum(1.f), {});
}

Spectrum GatherMediumToSurface(vrlis::SegmentChoice method, const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo,
                               const std::vector<Vrl>& vrls, Rng& rng, Spectrum throughput,
                               const GatherOptions& options) {
  const vrlis::Medium<float> medium = MediumOf(scene.medium);
  Rng own = rng.Split();
  const ConnectionEnd from{p, nf, true};
  auto share = [&](const vrlis::GatherSample<float>& s) { return GatherShareOf(from, s, options.bound); };
  auto reads = [](const vrlis::EffortCall<float>& call, double u) { return vrlis::SurfaceGatherReadsVrls(call, u); };
  return albedo * SumOverChunks(scene, vrls.data(), vrls.data() + vrls.size(), throughput * albedo, options, true, own,
                                share, reads,
                                [&](const vrlis::EffortCall<float>& call, Rng& numbers,
                                    const vrlis::VrlSegment<float>* segments, int n, auto& visit) {
                                  vrlis::GatherSurfaceVrls(method, p, nf, medium, segments, n,
                                                           [&] { return numbers.Uniform(); }, visit, call);
                                });
}

Spectrum SingleScattering(vrlis::SegmentChoice method, const Scene& scene, const CameraSegment& seg, Rng& rng,
                          bool after_vertex, const MediumShare* share) {
  const HomogeneousMedium& m = scene.medium;
  Spectrum sum;
  for (const PointLight& l : scene.lights.points) {
    if (l.fibonacci_beams) continue;  // delta directions: a camera ray never meets a beam
    if (after_vertex && GatheredAtVertex(scene, l)) continue;
    vrlis::PointLightGatherQuery<float> q{SegmentOf(seg), l.position, MediumOf(m)};
    const vrlis::GatherSample<float> s = vrlis::SamplePointLightGather(method, q, rng.Uniform());
    sum += l.intensity * (Connect(scene, l, s) * (share ? (*share)(s.camera_point) : 1.f));
  }
  for (const CollimatedRect& l : scene.lights.rects) {
    // A collimated beam: a distance uniform on the part of the segment inside the beam.
    auto [a, b] = l.Clip(seg.ray, seg.iv.a, seg.iv.b);
    const float u1 = rng.Uniform();
    if (!(b > a) || !std::isfinite(b)) continue;
    float u = std::min(a + u1 * (b - a), b);
    Vec3f x = seg.ray(u);
    std::optional<LightSample> ls = SampleLight(l, x);
    if (!ls) continue;  // on the beam's edge, to rounding
    float w = m.sigma_s * std::exp(-m.SigmaT() * (u - seg.iv.a)) * (b - a) * (share ? (*share)(x) : 1.f);
    float tr = scene.Connect(x, ls->source);
    if (tr > 0) sum += ls->value * (w * Phase(m.g, Dot(ls->wi, seg.ray.d)) * tr);
  }
  return sum;
}

float VertexLobe::operator()(Vec3f w) const {
  return cosine ? std::max(0.f, Dot(axis, w)) / kPi : vrlis::HenyeyGreenstein(g, Dot(axis, w));
}

bool GatheredAtVertex(const Scene& scene, const PointLight& light) {
  return !light.fibonacci_beams && scene.medium.Contains(light.position);
}

Spectrum VertexSingleScattering(const Scene& scene, Vec3f p, const VertexLobe& lobe, Rng& rng,
                                const MediumShare* share) {
  constexpr vrlis::SegmentChoice kEquiangular = vrlis::SegmentSamplers::Of<vrlis::EquiangularEntry>();
  Spectrum sum;
  for (const PointLight& l : scene.lights.points) {
    if (!GatheredAtVertex(scene, l)) continue;
    const float u1 = rng.Uniform(), u2 = rng.Uniform(), u3 = rng.Uniform();
    Vec3f to_light = l.position - p;
    if (!(Dot(to_light, to_light) > 0)) continue;
    Vec3f axis = Normalize(to_light);
    Ray ray{p, vrlis::SampleTwoPointDirection(axis, u1, u2)};
    float f = lobe(ray.d), pdf = vrlis::TwoPointDirectionPdf(axis, ray.d);
    if (!(f > 0) || !(pdf > 0) || !std::isfinite(pdf)) continue;
    SurfaceHit hit;
    bool found = scene.Intersect(ray, &hit);
    CameraSegment seg{ray, scene.medium.Clip(ray, found ? hit.t : kInfinity)};
    if (seg.iv.Empty()) continue;
    vrlis::PointLightGatherQuery<float> q{SegmentOf(seg), l.position, MediumOf(scene.medium)};
    const vrlis::GatherSample<float> s = vrlis::SamplePointLightGather(kEquiangular, q, u3);
    sum += l.intensity * (Connect(scene, l, s) * (f / pdf) * (share ? (*share)(s.camera_point) : 1.f));
  }
  return sum;
}

}  // namespace vrlis::integration
