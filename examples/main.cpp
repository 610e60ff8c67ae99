// vrl_render: renders one of the comparison scenes with the bidirectional VRL
// pipeline (or the reference path tracer) and writes EXR, PNG and a JSON summary.
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <utility>

#include <vrlis/core/query_rejections.hpp>
#include <vrlis_integration/query_log.hpp>
#include <vrlis_integration/renderer.hpp>
#include <vrlis_scenes/image_io.hpp>
#include <vrlis_scenes/scenes.hpp>

namespace {

constexpr int kUsageError = 2;

int Fail(const std::string& message) {
  std::fprintf(stderr, "vrl_render: error: %s\n", message.c_str());
  return kUsageError;
}

std::string JoinNames() {
  std::string s;
  for (auto n : vrlis::scenes::kSceneNames) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

std::string SamplerNames() {
  std::string s;
  for (auto m : vrlis::kSegmentSamplers) s += (s.empty() ? "" : ", ") + std::string(vrlis::Name(m));
  s += ", each optionally followed by";
  for (auto m : vrlis::kVrlSamplers) s += " +" + std::string(vrlis::Name(m));
  return s;
}

std::string Clock(double seconds) {
  long s = std::lround(std::max(0.0, seconds));
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

// One line redrawn in place: bar, percentage, passes, elapsed time and the time left.
void Progress(double fraction, int passes, double elapsed) {
  const int width = 40;
  fraction = std::clamp(fraction, 0.0, 1.0);
  int filled = static_cast<int>(std::lround(fraction * width));
  std::string eta = fraction > 0 ? Clock(elapsed / fraction - elapsed) : "?";
  std::fprintf(stderr, "\r[%s%s] %3d%%  %d passes  %s elapsed, %s left ",
               std::string(static_cast<std::size_t>(filled), '#').c_str(),
               std::string(static_cast<std::size_t>(width - filled), ' ').c_str(),
               static_cast<int>(std::lround(100 * fraction)), passes, Clock(elapsed).c_str(), eta.c_str());
  std::fflush(stderr);
}

// An EXR path from --out: ".exr" appended when the name has no extension (or one that is not
// an image's); empty for another image format, which this renderer does not write.
std::string ExrPath(const std::string& out) {
  auto ends = [&](const std::string& ext) {
    if (out.size() <= ext.size()) return false;
    for (std::size_t i = 0; i < ext.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(out[out.size() - ext.size() + i])) != ext[i]) return false;
    return true;
  };
  if (ends(".exr")) return out;
  for (const char* ext : {".png", ".jpg", ".jpeg", ".hdr", ".pfm", ".ppm", ".tif", ".tiff", ".bmp", ".json"})
    if (ends(ext)) return {};
  return out + ".exr";
}

double Rmse(const vrlis::integration::Film& a, const vrlis::integration::Film& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const vrlis::integration::Spectrum &p = a.pixels[i], &q = b.pixels[i];
    sum += (double(p.r) - q.r) * (double(p.r) - q.r) + (double(p.g) - q.g) * (double(p.g) - q.g) +
           (double(p.b) - q.b) * (double(p.b) - q.b);
  }
  return std::sqrt(sum / (3.0 * static_cast<double>(a.pixels.size())));
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene_name, sampler = vrlis::Name(vrlis::GatherSamplers{}), integrator = "vrl", gather = "all", out = "render.exr", reference;
  std::optional<float> g, sigma_s, sigma_a, exposure;
  float vpl_bound = vrlis::integration::TransportSettings{}.vpl_bound;
  std::string vrl_bound = "scene";
  double marginal_fraction = vrlis::integration::TransportSettings{}.marginal_fraction;
  int width = 256, height = 256, spp = 16, vrls = 64, threads = 0;
  double seconds = 0;
  std::uint64_t seed = 1, dump_every = 1000;
  std::string dump_queries, effort = vrlis::integration::TransportSettings{}.effort.on ? "on" : "off", pixel_samples = "stratified";
  bool no_jitter = false, no_caustics = false, quiet = false, json = false;

  CLI::App app{"Render a comparison scene with virtual ray lights (vrlis). Writes OUT (linear float RGB "
               "OpenEXR), a tonemapped sRGB PNG and a JSON summary beside it. Usage errors exit with code 2."};
  app.add_option("--scene", scene_name, "Scene: " + JoinNames())->required();
  app.add_option("--sampler", sampler, "Samplers (segment[+vrl]): " + SamplerNames())->capture_default_str();
  app.add_option("--integrator", integrator, "vrl (the VRL pipeline) or path (the reference path tracer)")
      ->capture_default_str();
  app.add_option("--gather", gather, "all (full transport), m2m (VRL medium-to-medium only) or m2s "
                                     "(VRL medium-to-surface only)")->capture_default_str();
  app.add_option("--g", g, "Henyey-Greenstein asymmetry in (-1, 1) (default: the scene's)");
  app.add_option("--sigma-s", sigma_s, "Scattering coefficient >= 0 (default: the scene's)");
  app.add_option("--sigma-a", sigma_a, "Absorption coefficient >= 0 (default: the scene's)");
  app.add_option("--width", width, "Image width in pixels")->capture_default_str();
  app.add_option("--height", height, "Image height in pixels")->capture_default_str();
  auto* spp_opt = app.add_option("--spp", spp, "Progressive passes (one sample per pixel and a fresh set "
                                               "of light paths each)")->capture_default_str();
  app.add_option("--time", seconds, "Render for this many seconds instead of --spp passes")->excludes(spp_opt);
  app.add_option("--vrls", vrls, "Light paths per pass")->capture_default_str();
  app.add_option("--effort", effort, "on: Russian roulette and splitting of every VRL gather by a price of variance "
                                     "learned from earlier passes (docs/maths.md#effort); off: every VRL gathered once. "
                                     "Either way auto takes each gather kind's model for the image by that price")
      ->capture_default_str();
  app.add_option("--marginal-fraction", marginal_fraction,
                 "With +marginal: the share of the medium-to-medium gathers, those of the largest predicted second "
                 "moments by the earlier passes, that take VrlMarginal's fit, the rest VrlPoint's density; the first "
                 "pass fits all (docs/maths.md#vrl-marginal-where); 1: every gather, every pass")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--seed", seed, "Random seed: the same seed gives the same image at any thread count")
      ->capture_default_str();
  app.add_option("--threads", threads, "Worker threads (0: all cores)")->capture_default_str();
  app.add_option("--out", out, "Output EXR path (.exr is appended if missing); the .png and .json share its stem")
      ->capture_default_str();
  app.add_option("--reference", reference, "A converged EXR of the same size: report the RMSE against it");
  app.add_option("--exposure", exposure, "PNG exposure multiplier (default: automatic)");
  app.add_option("--pixel-samples", pixel_samples, "stratified: each pixel's passes at the points of a scrambled "
                                                   "(0,2)-sequence (lower error of the mean, passes not independent); "
                                                   "independent: a fresh uniform point per pass")
      ->capture_default_str();
  app.add_option("--vpl-bound", vpl_bound, "VPLs at the light paths' diffuse vertices take the connections to them "
                                           "up to this geometry term (cos cos / r^2; cos / r^2 from the medium), "
                                           "the path-traced remainder the excess (Kollig and Keller 2004); 0: no VPLs")
      ->check(CLI::Range(0.f, std::numeric_limits<float>::max()))
      ->capture_default_str();
  app.add_option("--vrl-bound", vrl_bound, "The VRL gathers take their connections up to this geometry term (1 / r^2; "
                                           "cos / r^2 at a surface), the remainder the excess; inf: the gathers take "
                                           "all; 0: no light paths, a path tracer; scene: the scene's (1 in corner and cloud, "
                                           "inf elsewhere); auto: inf, 1 or 0.1, whichever the first two passes "
                                           "price lowest (docs/renderer.md#bound-choice)")
      ->capture_default_str();
  app.add_flag("--no-jitter", no_jitter, "Sample every pixel through its centre");
  app.add_flag("--no-caustics", no_caustics, "Stop light paths at a specular surface met before any "
                                             "scattering (what a path tracer with point lights can render)");
  app.add_flag("--quiet", quiet, "No progress bar and no summary line");
  app.add_flag("--json", json, "Print the JSON summary (also written beside the image) instead of the summary line");
  app.add_option("--dump-queries", dump_queries, "Write a sample of the medium-to-medium gather queries and their "
                                                 "image weights to this file (vrl integrator; format in "
                                                 "vrlis_integration/query_log.hpp)");
  app.add_option("--dump-every", dump_every, "Keep about one gather query in K for --dump-queries")
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "vrl_render: error: %s (see --help)\n", e.what());
    return kUsageError;
  }

  // Validate everything before any work or output.
  auto method = vrlis::ParseGatherSamplers(sampler);
  if (!method) return Fail("unknown sampler '" + sampler + "' (expected " + SamplerNames() + ")");
  if (integrator != "vrl" && integrator != "path") return Fail("unknown integrator '" + integrator + "' (expected vrl or path)");
  if (gather != "all" && gather != "m2m" && gather != "m2s") return Fail("unknown gather '" + gather + "' (expected all, m2m or m2s)");
  if (g && !(std::abs(*g) < 1)) return Fail("--g must lie in (-1, 1), got " + std::to_string(*g));
  if (!(vpl_bound >= 0) || !std::isfinite(vpl_bound)) return Fail("--vpl-bound must be finite and >= 0");
  std::optional<float> fixed_vrl_bound;
  if (vrl_bound != "auto" && vrl_bound != "scene") {
    char* end = nullptr;
    const float b = std::strtof(vrl_bound.c_str(), &end);
    if (vrl_bound.empty() || *end != '\0' || !(b >= 0))
      return Fail("--vrl-bound must be auto, scene or a number >= 0 (inf: no bound), got '" + vrl_bound + "'");
    fixed_vrl_bound = b;
  }
  if (sigma_s && !(*sigma_s >= 0 && std::isfinite(*sigma_s))) return Fail("--sigma-s must be finite and >= 0");
  if (sigma_a && !(*sigma_a >= 0 && std::isfinite(*sigma_a))) return Fail("--sigma-a must be finite and >= 0");
  if (width < 1 || height < 1) return Fail("--width and --height must be positive");
  if (width > 16384 || height > 16384) return Fail("--width and --height must be at most 16384");
  if (spp < 1) return Fail("--spp must be positive");
  if (app.count("--time") && !(seconds > 0 && std::isfinite(seconds))) return Fail("--time must be positive");
  if (vrls < 1) return Fail("--vrls must be positive");
  if (effort != "on" && effort != "off") return Fail("unknown --effort '" + effort + "' (expected on or off)");
  if (pixel_samples != "stratified" && pixel_samples != "independent")
    return Fail("unknown --pixel-samples '" + pixel_samples + "' (expected stratified or independent)");
  if (threads < 0) return Fail("--threads must be >= 0");
  if (dump_every < 1) return Fail("--dump-every must be positive");
  if (!dump_queries.empty() && integrator != "vrl") return Fail("--dump-queries needs --integrator vrl");
  if (!dump_queries.empty() && !vrlis::scenes::CanWrite(dump_queries)) return Fail("cannot write output file '" + dump_queries + "'");
  if (exposure && !(*exposure > 0 && std::isfinite(*exposure))) return Fail("--exposure must be positive");
  auto built = vrlis::scenes::BuildScene(scene_name, {g, sigma_s, sigma_a});
  if (!built) return Fail("unknown scene '" + scene_name + "' (expected " + JoinNames() + ")");
  if (!std::isfinite(built->scene.medium.SigmaT())) return Fail("--sigma-s + --sigma-a must be finite");
  if (gather == "m2s" && !built->has_surfaces)
    return Fail("--gather m2s: scene '" + scene_name + "' has no surfaces to gather at (use m2m or all)");
  std::optional<vrlis::integration::Film> ref;
  if (!reference.empty()) {
    std::string err;
    ref = vrlis::scenes::ReadExr(reference, &err);
    if (!ref) return Fail("cannot read reference '" + reference + "': " + err);
    if (ref->width != width || ref->height != height) return Fail("reference '" + reference + "' is not " + std::to_string(width) + "x" + std::to_string(height));
  }
  const std::string exr = ExrPath(out);
  if (exr.empty()) return Fail("--out '" + out + "' names another image format: vrl_render writes an .exr");
  out = exr;
  const std::string stem = out.substr(0, out.size() - 4), png = stem + ".png", json_path = stem + ".json";
  for (const std::string& p : {out, png, json_path})
    if (!vrlis::scenes::CanWrite(p)) return Fail("cannot write output file '" + p + "'");

  vrlis::integration::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.vrls_per_pass = vrls;
  settings.jitter = !no_jitter;
  settings.pixel_samples = pixel_samples == "stratified" ? vrlis::integration::PixelSamples::Stratified
                                                         : vrlis::integration::PixelSamples::Independent;
  settings.transport = built->transport;
  settings.transport.sampling = *method;
  settings.transport.light_caustics = !no_caustics;
  settings.transport.vpl_bound = vpl_bound;
  if (fixed_vrl_bound) settings.transport.vrl_bound = *fixed_vrl_bound;
  if (vrl_bound == "auto" && integrator == "vrl") settings.vrl_bounds = vrlis::integration::kAutoBounds;
  settings.transport.effort.on = effort == "on";
  settings.transport.marginal_fraction = marginal_fraction;
  std::atomic<int> rows_done{0};
  settings.rows_done = &rows_done;
  if (gather != "all") {
    settings.transport.medium_to_medium = gather == "m2m";
    settings.transport.medium_to_surface = gather == "m2s";
    settings.transport.direct = settings.transport.indirect = false;
    settings.transport.surface_to_surface = settings.transport.surface_to_medium = false;
    settings.transport.vrl_bound = vrlis::integration::kUnbounded;  // the gather whole: no remainder takes a share
    settings.vrl_bounds.clear();
  }
  vrlis::integration::QueryLog query_log(dump_every);
  if (!dump_queries.empty()) settings.transport.query_log = &query_log;
  const int workers = threads > 0 ? threads : tbb::info::default_concurrency();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(workers));
  std::unique_ptr<vrlis::integration::Renderer> renderer;
  if (integrator == "vrl")
    renderer = std::make_unique<vrlis::integration::VrlRenderer>(built->scene, settings);
  else
    renderer = std::make_unique<vrlis::integration::PathTracingRenderer>(built->scene, settings);

  const bool bar = !quiet && isatty(STDERR_FILENO);
  const bool timed = app.count("--time") > 0;
  vrlis::integration::Accumulator acc(width, height);
  std::uint64_t vrl_count = 0, gathers = 0;
  double pass_seconds = 0, pass_work = 0;
  auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  // The bar is redrawn from its own thread so that it moves within a pass (rows_done).
  std::atomic<int> passes_done{0};
  std::atomic<bool> finished{false};
  std::thread progress;
  if (bar)
    progress = std::thread([&] {
      for (bool last = false; !last;) {
        last = finished.load();
        double within = double(rows_done.load(std::memory_order_relaxed)) / height;
        double t = elapsed();
        Progress(timed ? t / seconds : (passes_done.load() + std::min(within, 1.0)) / spp, passes_done.load(), t);
        if (!last) std::this_thread::sleep_for(std::chrono::milliseconds(200));
      }
      std::fprintf(stderr, "\n");
    });
  for (int pass = 0;; ++pass) {
    if (timed ? (pass > 0 && elapsed() >= seconds) : pass >= spp) break;
    vrlis::integration::PassStats stats;
    rows_done.store(0);
    const vrlis::QueryRejections before = vrlis::RejectedQueries();
    acc.Add(renderer->RenderPass(seed, static_cast<std::uint64_t>(pass), &stats));
    // A rejected query contributes nothing: say so rather than leave a dark image unexplained.
    const vrlis::QueryRejections rejected = vrlis::RejectedQueries().since(before);
    if (rejected.total() > 0)
      std::fprintf(stderr, "%svrl_render: warning: pass %d rejected %llu gather queries: %s\n", bar ? "\n" : "", pass + 1,
                   static_cast<unsigned long long>(rejected.total()), vrlis::Describe(rejected).c_str());
    passes_done.store(pass + 1);
    vrl_count += stats.vrls;
    gathers += stats.gathers;
    pass_seconds += stats.seconds;
    pass_work += stats.work;
  }
  finished.store(true);
  if (progress.joinable()) progress.join();
  const double wall = elapsed();
  vrlis::integration::Film image = acc.Mean();
  // The bound the passes after the pilot took, where the renderer chose it.
  float used_bound = settings.transport.vrl_bound;
  auto bound_json = [](float b) { return b < vrlis::integration::kUnbounded ? nlohmann::json(b) : nlohmann::json("inf"); };
  nlohmann::json pilot = nlohmann::json::array();  // what the choice saw of each bound
  if (auto* vrl = dynamic_cast<vrlis::integration::VrlRenderer*>(renderer.get()))
    if (vrl->bound_choice().chosen()) {
      used_bound = *vrl->bound_choice().chosen();
      for (const auto& c : vrl->bound_choice().candidates())
        pilot.push_back({{"bound", bound_json(c.bound)}, {"variance", c.variance}, {"work", c.work}, {"pixels", c.pixels}});
    }

  nlohmann::json summary = {
      {"scene", scene_name}, {"integrator", integrator}, {"sampler", sampler}, {"gather", gather}, {"effort", effort},
      {"g", built->scene.medium.g}, {"sigma_s", built->scene.medium.sigma_s}, {"sigma_a", built->scene.medium.sigma_a},
      {"width", width}, {"height", height}, {"vrls_per_pass", vrls}, {"seed", seed}, {"threads", workers},
      {"jitter", !no_jitter}, {"pixel_samples", pixel_samples}, {"caustics", !no_caustics}, {"vpl_bound", vpl_bound}, {"marginal_fraction", marginal_fraction}, {"vrl_bound", bound_json(used_bound)}, {"vrl_bound_choice", vrl_bound}, {"passes", acc.passes()}, {"vrl_count", vrl_count},
      {"gathers", gathers}, {"wall_time_s", wall}, {"render_time_s", pass_seconds}, {"counted_work", pass_work},
      {"gathers_per_second", pass_seconds > 0 ? double(gathers) / pass_seconds : 0.0}};
  if (timed) summary["time_budget_s"] = seconds;
  if (!pilot.empty()) summary["vrl_bound_pilot"] = pilot;
  // With `auto`: the model each gather kind took at the end, and what the first price weighed
  // the models by (per pixel and pass; docs/maths.md#effort-models).
  if (auto* vrl = dynamic_cast<vrlis::integration::VrlRenderer*>(renderer.get()); vrl && vrl->ModelsPriced()) {
    const vrlis::EffortPrice& price = vrl->effort_price();
    auto name = [](vrlis::EffortModel m) {
      constexpr const char* kNames[] = {"rule", "accurate", "cheapest", "mixture"};  // in EffortModel's order
      static_assert(std::size(kNames) == vrlis::kEffortModels);
      return kNames[static_cast<int>(m)];
    };
    for (auto [kind, key] : {std::pair{vrlis::GatherKind::Medium, "medium"}, std::pair{vrlis::GatherKind::Surface, "surface"}}) {
      const vrlis::EffortPrice::ModelWeighing& w = price.first_weighing(kind);
      nlohmann::json changes = nlohmann::json::object();
      for (const auto* c : {&w.cheapest, &w.mixture, &w.accurate})
        if (c->known) changes[name(c->model)] = {{"dv", c->dv}, {"dt", c->dt}, {"share", c->share}};
      summary["effort_models"][key] = {{"model", name(price.model(kind))},
                                       {"first_weighing", {{"v_rule", w.v_rule}, {"t_rule", w.t_rule}, {"changes", changes}}}};
    }
    // Whether the pilot paired pixels under the accurate model, from its probe.
    summary["effort_models"]["pilot_probe"] = {{"medium_sum_sq", price.probe().medium_sum_sq},
                                               {"variance", price.probe().variance},
                                               {"pairs", price.pairs_pay()}};
  }
  if (ref) summary["rmse"] = Rmse(image, *ref);
  std::string err;
  if (!dump_queries.empty()) {
    std::vector<vrlis::integration::QueryRecord> records = query_log.Records();
    summary["dumped_queries"] = records.size();
    if (!vrlis::integration::WriteQueryLog(dump_queries, records, &err)) {
      std::fprintf(stderr, "vrl_render: error: %s\n", err.c_str());
      return 1;
    }
  }
  if (!vrlis::scenes::WriteExr(out, image, &err) ||
      !vrlis::scenes::WritePng(png, image, exposure ? *exposure : vrlis::scenes::AutoExposure(image), &err) ||
      !vrlis::scenes::WriteText(json_path, summary.dump(2) + "\n", &err)) {
    std::fprintf(stderr, "vrl_render: error: %s\n", err.c_str());
    return 1;
  }
  if (json)
    std::printf("%s\n", summary.dump().c_str());
  else if (!quiet)
    std::printf("%s: %s, %s, %dx%d, %d passes in %.1f s (%.3g VRL gathers/s) -> %s, %s, %s\n", scene_name.c_str(),
                integrator.c_str(), sampler.c_str(), width, height, acc.passes(), wall,
                pass_seconds > 0 ? double(gathers) / pass_seconds : 0.0, out.c_str(), png.c_str(), json_path.c_str());
  return 0;
}
