#include "vrlis_integration/renderer.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <chrono>
#include <limits>
#include <utility>
#include <vector>

#include "vrlis_integration/camera_paths.hpp"
#include "vrlis_integration/light_paths.hpp"
#include "vrlis_integration/path_tracer.hpp"
#include "vrlis_integration/work.hpp"

namespace vrlis::integration {
namespace {

// Calls f(ray, rng, x, y) for every pixel that `rendered(x, y)` names, in parallel over rows;
// the random stream of a pixel depends on (seed, pass, pixel) only.
template <typename F, typename Rendered>
Film ForEachPixel(const Scene& scene, const RenderSettings& s, std::uint64_t seed, std::uint64_t pass, F&& f,
                  Rendered&& rendered) {
  Film film(s.width, s.height);
  tbb::parallel_for(tbb::blocked_range<int>(0, s.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      for (int x = 0; x < s.width; ++x) {
        if (!rendered(x, y)) continue;
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
template <typename F>
Film ForEachPixel(const Scene& scene, const RenderSettings& s, std::uint64_t seed, std::uint64_t pass, F&& f) {
  return ForEachPixel(scene, s, seed, pass, std::forward<F>(f), [](int, int) { return true; });
}

// The effort control's pilot (EffortPrice::PilotDue): numbers of its own, never a pass's.
constexpr std::uint64_t kPilotPass = ~std::uint64_t(0);

double Since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

bool VrlRenderer::ModelsPriced() const {
  return settings_.transport.sampling == vrlis::GatherSamplers{vrlis::SegmentSamplers::Of<vrlis::AutoEntry>()};
}
bool VrlRenderer::Priced() const { return settings_.transport.effort.on || ModelsPriced(); }

Film VrlRenderer::RenderPass(std::uint64_t seed, std::uint64_t pass, PassStats* stats) {
  // Before its first price the effort control learns one from a pilot over a quarter of the
  // pixels, which the image does not keep: taking every gather once in every pixel, as the
  // first pass did, cost the room scene's 16-pass render half its time
  // (docs/maths.md#effort-pilot). Its cost is the pass's.
  if (!(Priced() && price_.PilotDue())) return RenderPixels(seed, pass, false, stats);
  PassStats pilot;
  RenderPixels(seed, kPilotPass, true, &pilot);
  Film film = RenderPixels(seed, pass, false, stats);
  if (stats) *stats += pilot;
  return film;
}

Film VrlRenderer::RenderPixels(std::uint64_t seed, std::uint64_t pass, bool pilot, PassStats* stats) {
  auto t0 = std::chrono::steady_clock::now();
  // Without a medium there are no light paths, and no VPLs to share the remainder's
  // connections with: the remainder then carries them all.
  // A pixel whose VRL bound is 0 is the path tracer's, and takes no light paths.
  const bool light_paths = scene_.medium.Present() && !scene_.lights.Powers().empty() &&
                           (bounds_.active() ? bounds_.LightPaths() : settings_.transport.vrl_bound > 0);
  TransportSettings transport = settings_.transport;
  if (!light_paths) transport.vpl_bound = 0;
  std::vector<Vpl> traced;
  double light_work = 0;
  std::vector<Vrl> vrls = light_paths ? TraceLightPaths(scene_, transport, settings_.vrls_per_pass, seed, pass,
                                                        transport.vpl_bound > 0 ? &traced : nullptr, &light_work)
                                      : std::vector<Vrl>{};
  const VplSet vpls(std::move(traced));
  const PathTracer path_tracer(scene_, settings_.transport);  // for pixels whose bound choice is 0
  std::atomic<std::uint64_t> gathers{0}, vertices{0};
  // Each pixel's counted work (work.hpp) outside its gather calls, and within them (their
  // records count it), summed in pixel order after the pass: with the effort control on,
  // what the price learns from.
  const std::size_t pixels = static_cast<std::size_t>(settings_.width) * static_cast<std::size_t>(settings_.height);
  std::vector<double> pixel_work(pixels), gather_work(pixels);
  const vrlis::EffortSettings& effort = settings_.transport.effort;
  vrlis::EffortSettings base = effort;
  // VrlMarginal's fits for the top marginal_fraction of the gathers by the earlier passes'
  // scores; the first pass (or the pilot) fits every gather.
  const bool scored = transport.sampling.vrl == vrlis::VrlSamplers::Of<vrlis::VrlMarginalEntry>() &&
                      transport.marginal_fraction < 1;
  if (scored && marginal_scores_.total() > 0) base.marginal_threshold = marginal_scores_.Threshold(transport.marginal_fraction);
  // With the control off `auto` still takes the image's model from the price, which then decides nothing else.
  const bool priced = Priced();
  if (priced) {
    vrlis::EffortSettings models = base;
    models.on = true, models.decide = effort.on;
    price_.BeginPass(models);
  }
  tbb::enumerable_thread_specific<vrlis::ScoreOctaves> pass_scores;
  const bool models_priced = ModelsPriced();
  // The pilot's pixel points are independent of every pass's (stratified points are a sequence over the passes).
  RenderSettings pixel_settings = settings_;
  if (pilot) pixel_settings.pixel_samples = PixelSamples::Independent;
  auto rendered = [pilot](int x, int y) { return !pilot || vrlis::EffortPrice::InPilot(x, y); };
  auto pixel = [&](const Ray& ray, Rng& rng, int x, int y) {
    const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(settings_.width) + static_cast<std::size_t>(x);
    TransportSettings pixel_transport = transport;
    if (bounds_.active()) pixel_transport.vrl_bound = bounds_.Bound(x, y);
    const bool path_traced = pixel_transport.vrl_bound == 0;  // the path tracer's pixel: no light paths
    GatherOptions options;
    vrlis::PixelRecord counted_only;  // where the price keeps no record: the calls' work and samples
    options.effort.record = &counted_only;
    // A path-traced pixel has no gathers: none of the effort control's per-pixel settings,
    // which cost about its own time again.
    if (!path_traced) {
      options.query_log = transport.query_log, options.weight_log = transport.weight_log;
      options.bound = pixel_transport.vrl_bound;
      if (scored) options.marginal_scores = &pass_scores.local();
      if (priced) {
        Rng choice(seed, pass, i, StreamPurpose::EffortModel);
        options.effort = price_.Pixel(x, y, [&] { return choice.Uniform(); });
        // In the pilot a share of the pixels of `auto`, both of a horizontal pair, also
        // gather their VRLs under the accurate model, for the statistics alone
        // (docs/maths.md#effort-accurate).
        const std::uint64_t left = static_cast<std::uint64_t>(y) * settings_.width + static_cast<std::uint64_t>(x - x % 2);
        options.pair = models_priced && price_.Pairs(x, y, Rng(seed, pass, left, StreamPurpose::EffortPair).Uniform());
      } else {
        options.effort.medium = options.effort.surface = base;
        options.effort.visit_work = kVisitWork;
      }
    }
    Spectrum L;
    const std::uint64_t vertices_before = ThreadVertices();
    {
      WorkScope scope(&pixel_work[i]);  // the pixel's own, from zero, whatever its thread did before
      ThreadWork() += renderer_work::kPixel;
      L = path_traced ? path_tracer.Li(ray, rng) : VrlRadiance(scene_, pixel_transport, vrls, vpls, ray, rng, options);
    }
    const vrlis::PixelRecord& record = *options.effort.record;
    gather_work[i] = record.medium.work + record.surface.work;
    gathers.fetch_add(static_cast<std::uint64_t>(record.medium.samples + record.surface.samples),
                      std::memory_order_relaxed);
    vertices.fetch_add(ThreadVertices() - vertices_before, std::memory_order_relaxed);
    return L;
  };
  // Each rendered pixel's value for the price: the RMS of its RGB (not finite: not rendered).
  auto values_of = [&](const Film& f, auto&& taken) {
    std::vector<double> v(pixels);
    for (std::size_t i = 0; i < pixels; ++i)
      v[i] = taken(int(i % std::size_t(settings_.width)), int(i / std::size_t(settings_.width)))
                 ? std::sqrt(f.pixels[i].MeanSquare())
                 : std::numeric_limits<double>::quiet_NaN();
    return v;
  };
  Film film;
  if (pilot && models_priced) {  // the probe first: whether the rest of the pilot pairs
    auto probe = [](int x, int y) { return vrlis::EffortPrice::InProbe(x, y); };
    RenderSettings probe_settings = pixel_settings;
    probe_settings.rows_done = nullptr;  // (the progress counts the pilot's rows once)
    film = ForEachPixel(scene_, probe_settings, seed, pass, pixel, probe);
    price_.EndProbe(values_of(film, probe));
    const Film rest = ForEachPixel(scene_, pixel_settings, seed, pass, pixel,
                                   [&](int x, int y) { return rendered(x, y) && !probe(x, y); });
    for (std::size_t i = 0; i < pixels; ++i) film.pixels[i] += rest.pixels[i];  // (disjoint; zero where not rendered)
  } else {
    film = ForEachPixel(scene_, pixel_settings, seed, pass, pixel, rendered);
  }
  double other = 0, work = light_work;
  for (std::size_t i = 0; i < pixels; ++i) other += pixel_work[i], work += pixel_work[i] + gather_work[i];
  std::vector<double> values = priced || bounds_.active() ? values_of(film, rendered) : std::vector<double>{};
  if (priced) price_.EndPass(values, other);
  if (bounds_.active() && !pilot) {
    for (std::size_t i = 0; i < pixels; ++i) pixel_work[i] += gather_work[i];
    bounds_.EndPass(settings_.width, values, pixel_work, light_work);
  }
  for (const vrlis::ScoreOctaves& s : pass_scores) marginal_scores_ += s;
  if (stats) *stats = {vrls.size(), gathers.load(), vertices.load(), Since(t0), work};
  return film;
}

Film PathTracingRenderer::RenderPass(std::uint64_t seed, std::uint64_t pass, PassStats* stats) {
  auto t0 = std::chrono::steady_clock::now();
  PathTracer pt(scene_, settings_.transport);
  Film film = ForEachPixel(scene_, settings_, seed, pass, [&](const Ray& ray, Rng& rng, int, int) { return pt.Li(ray, rng); });
  if (stats) *stats = {0, 0, 0, Since(t0)};
  return film;
}

}  // namespace vrlis::integration
