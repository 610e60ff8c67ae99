#include "decompose.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include <tbb/parallel_for.h>
#include <vrlis/samplers/full_product.hpp>
#include <vrlis/samplers/vrl_point.hpp>
#include <vrlis_integration/light_paths.hpp>

#include "image_stats.hpp"
#include "study_scene.hpp"

namespace vrlis::compare {
namespace {

// One quantity's passes in batches (replicates with their own seeds): the per-pass
// variance and its standard error from the spread of the batches.
class Batched {
 public:
  Batched(std::size_t batches, std::size_t values) : batches_(batches, PassStatistics(values)) {}
  void Add(std::size_t batch, const std::vector<double>& pass) { batches_[batch].Add(pass); }
  Estimate PassVariance() const { return MeanAndError(BatchVariances()); }
  // What this quantity's per-pass variance adds to `other`'s: a paired difference, batch by batch.
  Estimate VarianceOver(const Batched& other) const {
    std::vector<double> a = BatchVariances(), b = other.BatchVariances();
    for (std::size_t i = 0; i < a.size(); ++i) a[i] -= b[i];
    return MeanAndError(a);
  }

 private:
  std::vector<double> BatchVariances() const {
    std::vector<double> v;
    for (const PassStatistics& b : batches_) v.push_back(b.MeanPassVariance());
    return v;
  }
  static Estimate MeanAndError(const std::vector<double>& v) {
    vrlis::RunningMoments m;
    for (double x : v) m.add(x);
    return {m.mean(), m.standard_error()};
  }
  std::vector<PassStatistics> batches_;
};

std::vector<std::uint64_t> Seeds(const DecomposeConfig& c) {
  std::vector<std::uint64_t> seeds;
  for (int r = 0; r < c.replicates; ++r)
    seeds.push_back(vrlis::integration::SplitMix64(c.seed * 1000003 + static_cast<std::uint64_t>(r) + 0xDEC0ull));
  return seeds;
}

struct Variant {
  std::string name;
  std::unique_ptr<PassRenderer> renderer;
  double seconds = 0;
};

// A part's pass: variant `a`, minus variant `b` when the part is a difference.
struct Part {
  std::string name;
  std::size_t a, b;
  bool difference;
};

void RenderParts(const vrlis::integration::Scene& scene, const vrlis::integration::RenderSettings& whole, const DecomposeConfig& c,
                 DecomposeResult* out) {
  const vrlis::integration::TransportSettings& t = whole.transport;
  std::vector<Variant> variants;
  auto add = [&](const std::string& name, auto&& edit) {
    vrlis::integration::RenderSettings s = whole;
    s.transport.medium_to_medium = s.transport.medium_to_surface = s.transport.direct = s.transport.indirect = false;
    s.transport.surface_to_surface = s.transport.surface_to_medium = false;
    edit(s.transport);
    variants.push_back({name, std::make_unique<PassRenderer>(scene, s), 0});
    return variants.size() - 1;
  };
  const std::size_t all = add("all", [&](vrlis::integration::TransportSettings& x) { x = t; });
  const std::size_t none = add("none", [](vrlis::integration::TransportSettings&) {});
  std::vector<Part> parts;
  if (t.medium_to_medium)
    parts.push_back({"medium-to-medium", add("m2m", [](vrlis::integration::TransportSettings& x) { x.medium_to_medium = true; }), none, false});
  if (t.medium_to_surface)
    parts.push_back({"medium-to-surface", add("m2s", [](vrlis::integration::TransportSettings& x) { x.medium_to_surface = true; }), none, false});
  if (t.direct) {
    std::size_t surface = add("direct", [](vrlis::integration::TransportSettings& x) {
      x.direct = true;
      x.single_scattering = false;
    });
    std::size_t both = add("direct+single", [](vrlis::integration::TransportSettings& x) { x.direct = x.single_scattering = true; });
    if (t.single_scattering) parts.push_back({"single scattering", both, surface, true});
    parts.push_back({"direct", surface, none, false});
  }
  if (t.surface_to_surface)
    parts.push_back({"surface-to-surface", add("s2s", [](vrlis::integration::TransportSettings& x) { x.surface_to_surface = true; }), none, false});
  if (t.surface_to_medium)
    parts.push_back({"surface-to-medium", add("s2m", [](vrlis::integration::TransportSettings& x) { x.surface_to_medium = true; }), none, false});
  if (t.indirect)
    parts.push_back({"remainder", add("remainder", [](vrlis::integration::TransportSettings& x) { x.indirect = true; }), none, false});

  const std::size_t values = 3 * static_cast<std::size_t>(c.width) * static_cast<std::size_t>(c.height);
  const auto batches = static_cast<std::size_t>(c.replicates);
  std::vector<Batched> stats(parts.size(), Batched(batches, values));
  Batched total(batches, values);
  const std::vector<std::uint64_t> seeds = Seeds(c);
  double spent = 0;
  int pass = 0;
  std::size_t round = 0;
  for (; pass < 2 || spent < c.budget; ++pass)
    for (std::size_t rep = 0; rep < batches; ++rep, ++round) {
      std::vector<std::vector<double>> images(variants.size());
      for (std::size_t k = 0; k < variants.size(); ++k) {
        Variant& v = variants[(k + round) % variants.size()];
        double seconds = 0;
        images[(k + round) % variants.size()] =
            FromFilm(v.renderer->Render(Method{c.sampler, false}, seeds[rep], static_cast<std::uint64_t>(pass), &seconds));
        v.seconds += seconds;
        spent += seconds;
      }
      total.Add(rep, images[all]);
      for (std::size_t p = 0; p < parts.size(); ++p) {
        std::vector<double> image = images[parts[p].a];
        if (parts[p].difference)
          for (std::size_t i = 0; i < values; ++i) image[i] -= images[parts[p].b][i];
        stats[p].Add(rep, image);
      }
    }
  const double per_variant = static_cast<double>(pass) * static_cast<double>(batches);
  out->passes = static_cast<int>(per_variant);
  out->total_variance = total.PassVariance();
  out->total_seconds = variants[all].seconds / per_variant;
  out->base_seconds = variants[none].seconds / per_variant;
  for (std::size_t p = 0; p < parts.size(); ++p)
    out->parts.push_back({parts[p].name, stats[p].PassVariance(),
                          (variants[parts[p].a].seconds - variants[parts[p].b].seconds) / per_variant});
}

// The medium-to-medium integrand integrated over the camera segment at VRL point v: the
// midpoint rule in FullProduct's warp (which follows everything but visibility, so the
// ratio it leaves is nearly flat).
constexpr int kNodesU = 24, kNodesV = 12;

void Put(vrlis::integration::Spectrum s, std::size_t pixel, std::vector<double>* rgb) {
  (*rgb)[3 * pixel] = s.r;
  (*rgb)[3 * pixel + 1] = s.g;
  (*rgb)[3 * pixel + 2] = s.b;
}

vrlis::integration::Spectrum StepTwoByQuadrature(const vrlis::integration::Scene& scene, const vrlis::integration::CameraSegment& seg, const vrlis::integration::Vrl& vrl,
                                   float v) {
  const vrlis::integration::HomogeneousMedium& m = scene.medium;
  const vrlis::integration::Vec3f y = vrl.origin + v * vrl.dir;
  vrlis::FullProduct<float> warp(
      vrlis::MediumToMediumQuery(seg.ray.o, seg.ray.d, seg.iv.a, seg.iv.b, y, vrl.dir, m.g, m.SigmaT()));
  vrlis::integration::Spectrum sum;
  if (!warp.valid()) return sum;
  for (int i = 0; i < kNodesU; ++i) {
    float t = warp.sample((i + 0.5f) / kNodesU), p = warp.pdf(t);
    if (p > 0 && std::isfinite(p)) sum += vrlis::integration::MediumToMediumIntegrand(scene, seg, vrl, v, t) * (1 / p);
  }
  return sum * (1.f / kNodesU);
}

vrlis::VrlPoint<float> StepOne(const vrlis::integration::CameraSegment& seg, const vrlis::integration::Vrl& vrl) {
  return vrlis::VrlPoint<float>(vrlis::VrlPointQuery<float>{vrl.origin, vrl.dir, 0, vrl.length, seg.ray.o, seg.ray.d});
}

void SplitSteps(const vrlis::integration::Scene& scene, const vrlis::integration::RenderSettings& settings, const DecomposeConfig& c,
                DecomposeResult* out) {
  // Pixels whose centre sees the medium; each pass jitters its ray inside the pixel as the
  // renderer does, so the pixel filter's share is in the light paths' column.
  std::vector<std::pair<int, int>> pixels;
  auto segment = [&](float x, float y) {
    vrlis::integration::Ray ray = scene.camera.Generate(x, y, c.width, c.height);
    vrlis::integration::SurfaceHit hit;
    bool found = scene.Intersect(ray, &hit);
    return vrlis::integration::CameraSegment{ray, scene.medium.Clip(ray, found ? hit.t : vrlis::integration::kInfinity)};
  };
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x)
      if (!segment(x + 0.5f, y + 0.5f).iv.Empty()) pixels.emplace_back(x, y);
  // An even subset, in scan order, of at most max_pixels.
  const std::size_t keep = std::min(pixels.size(), static_cast<std::size_t>(c.max_pixels));
  for (std::size_t i = 0; i < keep; ++i) pixels[i] = pixels[i * pixels.size() / keep];
  pixels.resize(keep);
  out->step_pixels = static_cast<int>(pixels.size());
  if (pixels.empty() || !settings.transport.medium_to_medium) return;

  const std::size_t n = pixels.size(), batches = static_cast<std::size_t>(c.replicates);
  const std::size_t columns = c.samplers.size() + 2;  // each sampler's gather, step one alone, neither
  std::vector<Batched> stats(columns, Batched(batches, 3 * n));
  const std::vector<std::uint64_t> seeds = Seeds(c);
  auto start = std::chrono::steady_clock::now();
  int pass = 0;
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  for (; pass < 2 || elapsed() < c.step_budget; ++pass)
    for (std::size_t rep = 0; rep < batches; ++rep) {
      const std::vector<vrlis::integration::Vrl> vrls =
          vrlis::integration::TraceLightPaths(scene, settings.transport, c.vrls, seeds[rep], static_cast<std::uint64_t>(pass));
      std::vector<std::vector<double>> values(columns, std::vector<double>(3 * n));
      tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        vrlis::integration::Rng rng(seeds[rep], static_cast<std::uint64_t>(pass), i, vrlis::integration::StreamPurpose::Camera);
        const float jx = rng.Uniform(), jy = rng.Uniform();
        const vrlis::integration::CameraSegment seg = segment(static_cast<float>(pixels[i].first) + jx, static_cast<float>(pixels[i].second) + jy);
        if (seg.iv.Empty()) return;
        for (std::size_t s = 0; s < c.samplers.size(); ++s) {
          vrlis::integration::Spectrum sum;
          for (const vrlis::integration::Vrl& vrl : vrls) sum += GatherWith(c.samplers[s], scene, seg, vrl, rng);
          Put(sum, i, &values[s]);
        }
        vrlis::integration::Spectrum one, none;
        for (const vrlis::integration::Vrl& vrl : vrls) {
          vrlis::VrlPoint<float> vp = StepOne(seg, vrl);
          float v = vp.sample(rng.Uniform()), pv = vp.pdf(v);
          if (pv > 0 && std::isfinite(pv)) one += StepTwoByQuadrature(scene, seg, vrl, v) * (1 / pv);
          for (int j = 0; j < kNodesV; ++j) {
            float vj = vp.sample((j + 0.5f) / kNodesV), pj = vp.pdf(vj);
            if (pj > 0 && std::isfinite(pj)) none += StepTwoByQuadrature(scene, seg, vrl, vj) * (1 / (pj * kNodesV));
          }
        }
        Put(one, i, &values[columns - 2]);
        Put(none, i, &values[columns - 1]);
      });
      for (std::size_t k = 0; k < columns; ++k) stats[k].Add(rep, values[k]);
    }
  out->step_passes = pass * c.replicates;
  const Batched &one = stats[columns - 2], &neither = stats[columns - 1];
  for (std::size_t s = 0; s < c.samplers.size(); ++s)
    out->gathers.push_back({c.samplers[s], stats[s].PassVariance(), stats[s].VarianceOver(one)});
  out->step_one = one.VarianceOver(neither);
  out->paths_and_pixel_variance = neither.PassVariance();
}

}  // namespace

DecomposeResult Decompose(const DecomposeConfig& config) {
  StudyScene scene = BuildStudyScene(config.scene, {}, config.width, config.height, config.vrls);
  scene.settings.transport.vertex_single_scattering = !config.segment_scattering;
  if (config.vrl_bound) scene.settings.transport.vrl_bound = *config.vrl_bound;
  DecomposeResult out;
  out.config = config;
  out.g = scene.built.scene.medium.g;
  RenderParts(scene.built.scene, scene.settings, config, &out);
  SplitSteps(scene.built.scene, scene.settings, config, &out);
  return out;
}

}  // namespace vrlis::compare
