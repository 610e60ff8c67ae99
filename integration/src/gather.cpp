#include "vrlis_integration/gather.hpp"

#include <vrlis/core/two_point_direction.hpp>
#include <vrlis/gather/gather_vrls.hpp>
#include <vrlis/gather/medium_gather.hpp>
#include <vrlis/gather/point_light_gather.hpp>
#include <vrlis/samplers/equiangular.hpp>

#include "vrlis_integration/work.hpp"

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
// on the stack, the scene's visibility as the callback. `effort`: the call's, which says what
// its statistics measure (whether each gather is decided, whether the mixture is measured).
// `own`: the gathers' random numbers. `pair`, with stats: each chunk is gathered again under
// these settings, from the same random numbers, for the statistics alone
// (EffortStats::pair_delta): its samples are connected, not summed, and the sum and the
// numbers left for the rest are those of the call without it.
constexpr int kChunk = 8 * vrlis::kVrlPointBatch;

template <typename GatherShareOf, typename GatherChunk>
Spectrum SumOverChunks(const Scene& scene, const Vrl* first, const Vrl* last, Spectrum throughput,
                       const vrlis::EffortSettings& effort, EffortStats* stats, WeightLog* weight_log, Rng& own,
                       GatherShareOf&& share, GatherChunk&& gather_chunk, const vrlis::EffortSettings* pair = nullptr) {
  const bool decided = effort.on && effort.decide;
  if (!stats) pair = nullptr;
  Spectrum sum;
  vrlis::EffortTally tally, pair_tally;
  EffortStats taken;
  Spectrum pair_sum;
  double pair_work = 0, connect_work = 0;  // the pair's, and the occlusion rays of the call's samples
  for (const Vrl* chunk = first; chunk < last; chunk += kChunk) {
    const int n = static_cast<int>(std::min<std::ptrdiff_t>(kChunk, last - chunk));
    vrlis::VrlSegment<float> segments[kChunk];
    float weights[kChunk];  // for decided gathers, and VrlMarginal's choice of fits
    int samples[kChunk];
    double sum_y[kChunk], sum_y2[kChunk];  // per VRL, of its samples' unweighted contributions; decided, with stats
    for (int i = 0; i < n; ++i) segments[i] = SegmentOf(chunk[i]);
    for (int i = 0; i < n; ++i) weights[i] = (throughput * chunk[i].flux).Rms();
    const bool split = stats && decided;  // undecided, every VRL takes one sample
    if (split)
      for (int i = 0; i < n; ++i) samples[i] = 0, sum_y[i] = sum_y2[i] = 0;
    auto connect = [&](int i, const vrlis::GatherSample<float>& s, float effort_weight) {
      ThreadWork() += renderer_work::kConnect;  // this function's own, beyond its ray
      Spectrum x = chunk[i].flux * (Connect(scene, s) * share(s) * effort_weight);
      sum += x;
      if (weight_log) weight_log->Record(effort_weight, s.weight, (throughput * x).Rms());
      if (!stats) return;
      ++taken.gathers;
      if (!decided && !(s.over_equiangular > 0 || s.over_mixture > 0)) return;  // nothing else to learn from it
      double y = (throughput * x).Rms() / effort_weight;
      if (decided) {
        taken.measured += effort_weight * y * y;
        (effort_weight > 1 ? taken.roulette_excess : taken.split_excess) += effort_weight * y * y * (effort_weight - 1);
      }
      if (s.over_equiangular > 0) taken.cheapest_excess += vrlis::Sqr(effort_weight * y) * (s.over_equiangular - 1);
      if (s.over_mixture > 0) taken.mixture_excess += vrlis::Sqr(effort_weight * y) * (s.over_mixture - 1);
      if (split) ++samples[i], sum_y[i] += y, sum_y2[i] += y * y;
    };
    Rng same = own;
    {
      WorkScope scope(&connect_work);  // the library counts its own work in the tally
      gather_chunk(effort, own, segments, weights, n, connect, &tally);
    }
    if (pair) {
      auto measure = [&](int i, const vrlis::GatherSample<float>& s, float) {
        pair_sum += chunk[i].flux * (Connect(scene, s) * share(s));
      };
      WorkScope scope(&pair_work, false);  // for the statistics alone: not the pixel's work
      gather_chunk(*pair, same, segments, weights, n, measure, &pair_tally);
    }
    for (int i = 0; split && i < n; ++i)
      if (samples[i] > 1) {
        double k = samples[i], mean = sum_y[i] / k;
        taken.split_within += std::max(0.0, (sum_y2[i] - k * mean * mean) / (k - 1));
        taken.split_second += sum_y2[i] / k;
      }
  }
  ThreadWork() += tally.work;
  if (stats) {
    taken.predicted = tally.predicted;
    taken.sample_work = tally.sample_work + connect_work;
    constexpr int kRule = static_cast<int>(vrlis::EffortModel::Chosen);
    constexpr int kCheapest = static_cast<int>(vrlis::EffortModel::Cheapest);
    constexpr int kMixture = static_cast<int>(vrlis::EffortModel::Mixture);
    taken.rule_samples = double(tally.model_samples[kRule]);
    if (!effort.measure_mixture) taken.rule_work = tally.model_work[kRule];  // the measuring's not the rule's
    taken.cheapest_samples = double(tally.model_samples[kCheapest]);
    taken.cheapest_work = tally.model_work[kCheapest];
    taken.mixture_samples = double(tally.model_samples[kMixture]);
    taken.mixture_work = tally.model_work[kMixture];
    if (effort.measure_mixture) taken.mixture_measured = taken.rule_samples;
    if (pair) {
      constexpr int kAccurate = static_cast<int>(vrlis::EffortModel::Accurate);
      taken.accurate_samples = double(pair_tally.model_samples[kAccurate]);
      taken.accurate_work = pair_tally.model_work[kAccurate];
      taken.pair_delta = throughput * (pair_sum + sum * -1.f);
      taken.pair_work = pair_work + pair_tally.work;
    }
    *stats += taken;
  }
  return sum;
}

// The gather's share of a sample's connection from `from` to the VRL point (share.hpp).
float GatherShareOf(const ConnectionEnd& from, const vrlis::GatherSample<float>& s, float bound) {
  return bound < kUnbounded ? GatherShare(GeometryTerm(from, {s.light_point, {}, false}), bound) : 1.f;
}

// The medium-to-medium sum over the VRLs [first, last).
Spectrum GatherEach(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg, const Vrl* first,
                    const Vrl* last, Rng& rng, QueryLog* log, Spectrum throughput,
                    const vrlis::EffortSettings& effort, EffortStats* stats, WeightLog* weight_log, float bound,
                    const vrlis::EffortSettings* pair, vrlis::ScoreOctaves* marginal_scores) {
  const vrlis::RaySegment<float> camera = SegmentOf(seg);
  const vrlis::Medium<float> medium = MediumOf(scene.medium);
  Rng own = rng.Split();
  if (log)
    for (const Vrl* vrl = first; vrl != last; ++vrl)
      log->Record({camera, SegmentOf(*vrl), medium}, (throughput * vrl->flux).Rms());
  auto share = [&](const vrlis::GatherSample<float>& s) {
    return GatherShareOf({s.camera_point, {}, false}, s, bound);
  };
  return SumOverChunks(
      scene, first, last, throughput, effort, stats, weight_log, own, share,
      [&](const vrlis::EffortSettings& settings, Rng& numbers, const vrlis::VrlSegment<float>* segments,
          const float* weights, int n, auto& connect, vrlis::EffortTally* tally) {
        // (The pair's gathers, for the statistics alone, are not scored.)
        vrlis::GatherMediumVrls(method, settings, camera, medium, segments, weights, n,
                                [&] { return numbers.Uniform(); }, connect, tally,
                                &settings == &effort ? marginal_scores : nullptr);
      },
      pair);
}

}  // namespace

Spectrum GatherMediumToMedium(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg,
                              const Vrl& vrl, Rng& rng, QueryLog* log, Spectrum throughput) {
  return GatherEach(method, scene, seg, &vrl, &vrl + 1, rng, log, throughput, {}, nullptr, nullptr, kUnbounded,
                    nullptr, nullptr);
}

Spectrum GatherMediumToMedium(vrlis::GatherSamplers method, const Scene& scene, const CameraSegment& seg,
                              const std::vector<Vrl>& vrls, Rng& rng, QueryLog* log, Spectrum throughput,
                              const vrlis::EffortSettings& effort, EffortStats* stats, WeightLog* weight_log,
                              float bound, const vrlis::EffortSettings* pair, vrlis::ScoreOctaves* marginal_scores) {
  return GatherEach(method, scene, seg, vrls.data(), vrls.data() + vrls.size(), rng, log, throughput, effort, stats,
                    weight_log, bound, pair, marginal_scores);
}

Spectrum GatherMediumToSurface(vrlis::SegmentChoice method, const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo,
                               const std::vector<Vrl>& vrls, Rng& rng, Spectrum throughput,
                               const vrlis::EffortSettings& effort, EffortStats* stats, WeightLog* weight_log,
                               float bound) {
  const vrlis::Medium<float> medium = MediumOf(scene.medium);
  Rng own = rng.Split();
  const ConnectionEnd from{p, nf, true};
  auto share = [&](const vrlis::GatherSample<float>& s) { return GatherShareOf(from, s, bound); };
  return albedo * SumOverChunks(scene, vrls.data(), vrls.data() + vrls.size(), throughput * albedo, effort, stats,
                                weight_log, own, share,
                                [&](const vrlis::EffortSettings& settings, Rng& numbers,
                                    const vrlis::VrlSegment<float>* segments, const float* weights, int n,
                                    auto& connect, vrlis::EffortTally* tally) {
                                  vrlis::GatherSurfaceVrls(method, settings, p, nf, medium, segments, weights, n,
                                                           [&] { return numbers.Uniform(); }, connect, tally);
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
