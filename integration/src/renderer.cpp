#include "vrlis_integration/renderer.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <utility>
#include <vector>

#include "vrlis_integration/camera_paths.hpp"
#include "vrlis_integration/light_paths.hpp"
#include "vrlis_integration/path_tracer.hpp"
#include "vrlis_integration/work.hpp"

namespace vrlis::integration {
namespace {

// Calls f(ray, rng, x, y) for every pixel, in parallel over rows; the random stream of a
// pixel depends on (seed, pass, pixel) only.
template <typename F>
Film ForEachPixel(const Scene& scene, const RenderSettings& s, std::uint64_t seed, std::uint64_t pass, F&& f) {
  Film film(s.width, s.height);
  tbb::parallel_for(tbb::blocked_range<int>(0, s.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      for (int x = 0; x < s.width; ++x) {
        const std::uint64_t pixel = static_cast<std::uint64_t>(y) * s.width + x;
        Rng rng(seed, pass, pixel, StreamPurpose::Camera);
        PixelPoint j;
        if (s.jitter) {
          // The stream's first two numbers are the jitter's whichever the kind of sample,
          // so the rest of the path meets the same numbers: the kinds differ in the jitter only.
          j = {rng.Uniform(), rng.Uniform()};
          if (s.pixel_samples == PixelSamples::Stratified) j = StratifiedPixelPoint(seed, pixel, pass);
        }
        Ray ray = scene.camera.Generate(x + j.x, y + j.y, s.width, s.height);
        film.at(x, y) = f(ray, rng, x, y);
      }
      if (s.rows_done) s.rows_done->fetch_add(1, std::memory_order_relaxed);
    }
  });
  return film;
}

double Since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

Film VrlRenderer::RenderPass(std::uint64_t seed, std::uint64_t pass, PassStats* stats) {
  auto t0 = std::chrono::steady_clock::now();
  // Without a medium there are no light paths, and no VPLs to share the remainder's
  // connections with: the remainder then carries them all.
  const bool light_paths = scene_.medium.Present() && !scene_.lights.Powers().empty();
  TransportSettings transport = settings_.transport;
  if (!light_paths) transport.vpl_bound = 0;
  std::vector<Vpl> traced;
  std::vector<Vrl> vrls = light_paths ? TraceLightPaths(scene_, transport, settings_.vrls_per_pass, seed, pass,
                                                        transport.vpl_bound > 0 ? &traced : nullptr)
                                      : std::vector<Vrl>{};
  const VplSet vpls(std::move(traced));
  std::atomic<std::uint64_t> gathers{0};
  // Each pixel's counted work (work.hpp), summed in pixel order after the pass: what the price
  // learns from, with the effort control on.
  std::vector<double> pixel_work(static_cast<std::size_t>(settings_.width) * settings_.height);
  const vrlis::EffortSettings& effort = settings_.transport.effort;
  EffortPrice::PixelStats* learned = effort.on ? &price_.BeginPass() : nullptr;
  vrlis::EffortSettings medium_effort = effort, surface_effort = effort;
  medium_effort.price = price_.price(GatherKind::Medium);  // from the passes before this one
  surface_effort.price = price_.price(GatherKind::Surface);
  medium_effort.within = price_.within(GatherKind::Medium);
  surface_effort.within = price_.within(GatherKind::Surface);
  // VrlMarginal's fits for the top marginal_fraction of the gathers by the earlier passes'
  // scores; the first pass fits every gather.
  const bool scored = transport.sampling.vrl == vrlis::VrlSamplers::Of<vrlis::VrlMarginalEntry>() &&
                      transport.marginal_fraction < 1;
  if (scored && marginal_scores_.total() > 0)
    medium_effort.marginal_threshold = marginal_scores_.Threshold(transport.marginal_fraction);
  tbb::enumerable_thread_specific<vrlis::ScoreOctaves> pass_scores;
  const bool pairs_models = transport.sampling == vrlis::GatherSamplers{vrlis::SegmentSamplers::Of<vrlis::AutoEntry>()};
  // A pixel's radiance and its counted work, from zero (the pixel's own, not its thread's).
  auto counted = [&](std::size_t i, auto&& radiance) {
    WorkScope scope(&pixel_work[i]);
    ThreadWork() += renderer_work::kPixel;
    return radiance();
  };
  Film film = ForEachPixel(scene_, settings_, seed, pass, [&](const Ray& ray, Rng& rng, int x, int y) {
    GatherCount count;
    if (scored) count.marginal_scores = &pass_scores.local();
    const std::size_t i = static_cast<std::size_t>(y) * settings_.width + x;
    if (!effort.on) {
      const Spectrum L = counted(
          i, [&] { return VrlRadiance(scene_, transport, vrls, vpls, ray, rng, &count, medium_effort, surface_effort); });
      gathers.fetch_add(count.Total(), std::memory_order_relaxed);
      return L;
    }
    vrlis::EffortSettings m = medium_effort, s = surface_effort;
    m.call_demand = price_.call_demand(GatherKind::Medium, x, y);
    s.call_demand = price_.call_demand(GatherKind::Surface, x, y);
    Rng choice(seed, pass, static_cast<std::uint64_t>(y) * settings_.width + x, StreamPurpose::EffortModel);
    m.model = price_.model(GatherKind::Medium, choice.Uniform());
    s.model = price_.model(GatherKind::Surface, choice.Uniform());
    m.decide = price_.decide(GatherKind::Medium, choice.Uniform());
    s.decide = price_.decide(GatherKind::Surface, choice.Uniform());
    m.measure_mixture = m.model == vrlis::EffortModel::Chosen && price_.measure_mixture(GatherKind::Medium, choice.Uniform());
    s.measure_mixture = s.model == vrlis::EffortModel::Chosen && price_.measure_mixture(GatherKind::Surface, choice.Uniform());
    // The remainder is split where it asks for more paths, never rouletted: its paths cost too
    // little where it asks for fewer (room: 0.3 ms of a 78 ms pass) to repay larger weights.
    const double demand = price_.remainder_demand(x, y);  // NaN or below 1: one path
    const double rate = demand > 1 ? std::min(demand, std::max(1.0, effort.ceiling)) : 1.0;
    // In the first pass a share of the pixels of `auto`, both of a horizontal pair, also
    // gather their VRLs under the accurate model, for the statistics alone
    // (docs/maths.md#effort-accurate); the pairing's stream is drawn only where it can pair.
    const bool paired =
        pairs_models && price_.pairs() &&
        price_.pair(Rng(seed, pass, static_cast<std::uint64_t>(y) * settings_.width + (x - x % 2), StreamPurpose::EffortPair)
                        .Uniform());
    vrlis::EffortSettings pair;
    if (paired) {
      pair = m;
      pair.decide = pair.measure_mixture = false;
      pair.model = vrlis::EffortModel::Accurate;
    }
    const Spectrum L = counted(i, [&] {
      return VrlRadiance(scene_, transport, vrls, vpls, ray, rng, &count, m, s, rate, paired ? &pair : nullptr);
    });
    gathers.fetch_add(count.Total(), std::memory_order_relaxed);
    count.medium_effort.pair_pixel = paired ? 1 : 0;
    learned->medium[i] = count.medium_effort;
    learned->surface[i] = count.surface_effort;
    learned->remainder[i] = count.remainder;
    return L;
  });
  double work = 0;
  for (double w : pixel_work) work += w;
  if (effort.on) price_.Add(film, work);
  for (const vrlis::ScoreOctaves& s : pass_scores) marginal_scores_ += s;
  if (stats) *stats = {vrls.size(), gathers.load(), Since(t0), work};
  return film;
}

Film PathTracingRenderer::RenderPass(std::uint64_t seed, std::uint64_t pass, PassStats* stats) {
  auto t0 = std::chrono::steady_clock::now();
  PathTracer pt(scene_, settings_.transport);
  Film film = ForEachPixel(scene_, settings_, seed, pass, [&](const Ray& ray, Rng& rng, int, int) { return pt.Li(ray, rng); });
  if (stats) *stats = {0, 0, Since(t0)};
  return film;
}

}  // namespace vrlis::integration
