// vrl_compare: the equal-time study of the camera samplers. For every scene and g, every
// sampler renders the same passes in independent replicates; the output is the efficiency
// of each (1 / (per-pass variance x seconds per pass)) relative to Novák's with a 95%
// interval, a verdict that says "best" only when the interval separates the winner from the
// runner-up, and the error against a mixture reference. With --decompose: where each
// scene's noise lives instead; with --gather-weights: the tails of the gather samples'
// weights. Writes under --out (one folder per study, summary.md and summary.json; or
// decompose/<scene>.json; or gather_weights.json) and prints the table. Every argument is
// checked before anything is written.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "decompose.hpp"
#include "gather_weights.hpp"
#include <vrlis_scenes/image_io.hpp>
#include "image_stats.hpp"
#include <vrlis_scenes/scenes.hpp>
#include "study.hpp"

namespace {

using vrlis::compare::DecomposeResult;
using vrlis::compare::SamplerName;
using vrlis::compare::StudyConfig;
using vrlis::compare::StudyResult;

int Fail(const std::string& message) {
  std::fprintf(stderr, "vrl_compare: %s\n", message.c_str());
  return 2;
}

std::string StudyName(const StudyConfig& c) {
  std::ostringstream s;
  s << c.scene << "_g" << c.g;
  return s.str();
}

nlohmann::json ToJson(const vrlis::compare::RatioInterval& r) {
  return {{"point", r.point}, {"low", r.low}, {"high", r.high}};
}
nlohmann::json ToJson(const vrlis::compare::Estimate& e) { return {{"value", e.value}, {"se", e.standard_error}}; }

nlohmann::json Progressions(const std::vector<vrlis::compare::Progression>& replicates) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : replicates) out.push_back({{"seconds", p.seconds}, {"rmse", p.rmse}});
  return out;
}

bool WriteStudy(const StudyResult& r, const std::string& dir, std::string* error) {
  const StudyConfig& c = r.config;
  std::filesystem::create_directories(dir);
  nlohmann::json samplers = nlohmann::json::array();
  vrlis::integration::Film reference = vrlis::compare::ToFilm(r.reference_image, c.width, c.height);
  float exposure = vrlis::scenes::AutoExposure(reference);
  for (const auto& s : r.samplers) {
    samplers.push_back({{"sampler", SamplerName(s.sampler)}, {"passes", s.passes}, {"seconds_per_pass", s.seconds},
                        {"variance", s.variance}, {"efficiency", s.efficiency}, {"to_baseline", ToJson(s.to_baseline)},
                        {"to_best_published", ToJson(s.to_best_published)},
                        {"error_to_noise", s.error_to_noise.ratio}, {"error_dof", s.error_to_noise.dof},
                        {"error_range", {s.error_to_noise.low, s.error_to_noise.high}}, {"verdict", s.verdict},
                        {"replicates", {{"variance", s.replicates.variance}, {"seconds", s.replicates.seconds}}},
                        {"progression", Progressions(s.progression)}});
    if (s.to_without_effort) samplers.back()["to_without_effort"] = ToJson(*s.to_without_effort);
    if (!vrlis::scenes::WritePng(dir + "/" + SamplerName(s.sampler) + ".png",
                              vrlis::compare::ToFilm(s.image, c.width, c.height), exposure, error))
      return false;
  }
  nlohmann::json mixture = nlohmann::json::array();
  for (auto s : c.samplers) mixture.push_back(SamplerName(s));
  nlohmann::json j = {{"scene", c.scene}, {"g", c.g}, {"vrl_only", c.vrl_only}, {"margin", c.margin},
                      {"baseline", SamplerName(vrlis::compare::kBaseline)}, {"best_published", SamplerName(r.best_published)}, {"width", c.width}, {"height", c.height}, {"vrls", c.vrls},
                      {"budget", c.budget}, {"min_passes", c.min_passes}, {"effort_floor", c.effort_floor}, {"replicates", c.replicates}, {"seed", c.seed},
                      {"passes_per_replicate", r.passes_per_replicate}, {"verdict", r.verdict},
                      {"top_vs_runner_up", ToJson(r.top_vs_runner_up)}, {"resolution", r.resolution},
                      {"sampler_noise", r.sampler_noise}, {"samplers", samplers},
                      {"reference", {{"mixture", mixture}, {"passes", r.reference_passes},
                                     {"seconds", r.reference_seconds}, {"cached", r.reference_cached},
                                     {"noise", r.reference_noise}, {"dof", r.reference_dof}}}};
  return vrlis::scenes::WritePng(dir + "/reference.png", reference, exposure, error) &&
         vrlis::scenes::WriteText(dir + "/result.json", j.dump(2) + "\n", error);
}

std::string Interval(const vrlis::compare::RatioInterval& r) {
  char s[96];
  std::snprintf(s, sizeof s, "%.2f (%.2f-%.2f)", r.point, r.low, r.high);
  return s;
}

// One row per study and sampler.
std::string SummaryTable(const std::vector<StudyResult>& results) {
  std::ostringstream t;
  t << "| scene | g | sampler | passes | ms / pass | variance / pass | efficiency / "
    << vrlis::compare::kBaseline.sampler.segment.name() << " (95% interval) | error² / noise² (range if unbiased) | verdict |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : results)
    for (const auto& s : r.samplers) {
      const vrlis::compare::ErrorToNoise& e = s.error_to_noise;
      const char* bold = e.Outside() ? "**" : "";
      char line[384];
      std::snprintf(line, sizeof line, "| %s | %g | %s | %d | %.3g | %.3g | %s | %s%.2f%s (%.2f-%.2f) | %s |\n",
                    r.config.scene.c_str(), r.config.g, SamplerName(s.sampler).c_str(), s.passes, 1000 * s.seconds,
                    s.variance, Interval(s.to_baseline).c_str(), bold, e.ratio, bold, e.low, e.high, s.verdict.c_str());
      t << line;
    }
  return t.str();
}

// What the run could tell apart, in words.
std::string Resolution(const StudyResult& r) {
  auto [fewest, most] = std::minmax_element(r.samplers.begin(), r.samplers.end(),
                                            [](const auto& a, const auto& b) { return a.passes < b.passes; });
  char s[512];
  std::snprintf(s, sizeof s,
                "%s: %d to %d passes per sampler (in %d replicates; each stops at its budget); efficiency ratios "
                "resolved to x%.2f (median 95%% half-width); %s, most efficient over the next %s%s\n",
                StudyName(r.config).c_str(), fewest->passes, most->passes, r.config.replicates,
                r.resolution, r.verdict.c_str(), Interval(r.top_vs_runner_up).c_str(),
                r.top_vs_runner_up.low <= r.config.margin && r.top_vs_runner_up.high > r.config.margin
                    ? " (undecided: the interval still holds the margin at the extended budget)"
                    : "");
  return s;
}

nlohmann::json DecompositionJson(const DecomposeResult& d) {
  nlohmann::json parts = nlohmann::json::array(), gathers = nlohmann::json::array();
  for (const auto& p : d.parts)
    parts.push_back({{"part", p.name}, {"variance", ToJson(p.variance)}, {"seconds_per_pass", p.seconds}});
  for (const auto& s : d.gathers) gathers.push_back({{"sampler", SamplerName(s.sampler)}, {"variance", ToJson(s.variance)}, {"step_two", ToJson(s.step_two)}});
  return {{"scene", d.config.scene}, {"g", d.g}, {"width", d.config.width}, {"height", d.config.height},
          {"vrls", d.config.vrls}, {"sampler", SamplerName(d.config.sampler)}, {"passes", d.passes},
          {"parts", parts}, {"total_variance", ToJson(d.total_variance)}, {"total_seconds", d.total_seconds},
          {"base_seconds", d.base_seconds},
          {"steps", {{"pixels", d.step_pixels}, {"max_pixels", d.config.max_pixels}, {"passes", d.step_passes},
                     {"paths_and_pixel_variance", ToJson(d.paths_and_pixel_variance)},
                     {"step_one", ToJson(d.step_one)}, {"gathers", gathers}}}};
}

nlohmann::json GatherWeightsJson(const vrlis::compare::GatherWeightsResult& r) {
  const vrlis::compare::GatherWeightsConfig& c = r.config;
  return {{"scene", c.scene}, {"g", r.g}, {"method", SamplerName(c.method)}, {"width", c.width},
          {"height", c.height}, {"vrls", c.vrls}, {"passes", c.passes}, {"seed", c.seed},
          {"effort_floor", c.effort_floor}, {"samples", r.samples}, {"non_finite", r.non_finite},
          {"largest_effort_weight", r.largest_effort_weight}, {"mean_pixel", r.mean_pixel},
          {"largest_contribution", r.largest_contribution}, {"quantile", vrlis::compare::kGatherWeightsQuantile},
          {"quantile_contribution", r.quantile_contribution}, {"seconds", r.seconds}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Equal-time study of the vrlis camera samplers on the four scenes, with confidence intervals."};
  std::vector<std::string> scenes = {"bidirectional", "room"};
  std::vector<float> gs = {-0.9f, 0.5f, 0.9f};
  std::vector<std::string> sampler_names;
  bool full = false, decompose = false, with_effort = false, segment_scattering = false, gather_weights = false;
  StudyConfig base;
  double reference_factor = 2, decompose_seconds = 20, step_seconds = 15;
  int threads = 2, passes = vrlis::compare::GatherWeightsConfig{}.passes;
  std::string out = "out/compare";
  app.add_flag("--full", full, "Every scene, g in {-0.9,-0.5,0,0.5,0.9}, budget 12 s (the published run)");
  app.add_flag("--vrl-only", base.vrl_only, "The image of the two VRL gathers alone (medium-to-medium and "
                                          "medium-to-surface), as the thesis measured, not the whole transport");
  app.add_flag("--with-effort", with_effort, "Every sampler also with the effort control on (NAME+effort; "
                                           "a sampler is named so in --samplers too)");
  app.add_flag("--decompose", decompose, "Where the noise lives: per part of transport, and step one versus two");
  std::optional<float> vrl_bound;
  app.add_option("--vrl-bound", vrl_bound, "--decompose: the VRL gathers take their connections up to this geometry "
                                           "term, the remainder the rest (inf: none shared; default: each scene's)");
  app.add_flag("--segment-scattering", segment_scattering, "--decompose: path-traced parts estimate point-light "
               "single scattering along each segment, not jointly at the vertex before it");
  app.add_flag("--gather-weights", gather_weights, "The tails of the gather samples' weights, each scene at its "
               "default g, each sampler (default cauchy-sum, auto) with the effort control off and on");
  app.add_option("--passes", passes, "--gather-weights: passes per scene and method, >= 2 (the first, which "
                 "takes every gather once to price them, is not recorded)")->capture_default_str();
  std::string scene_names;
  for (auto n : vrlis::scenes::kSceneNames) scene_names += (scene_names.empty() ? "" : ", ") + std::string(n);
  app.add_option("--scenes", scenes, "Scenes (" + scene_names + ")")->delimiter(',')->capture_default_str();
  app.add_option("--g", gs, "Henyey-Greenstein g values, each in (-1, 1)")->delimiter(',')->capture_default_str();
  app.add_option("--samplers", sampler_names, "Camera samplers, the baseline " + SamplerName(vrlis::compare::kBaseline) + " among them (default: all)")->delimiter(',');
  app.add_option("--min-passes", base.min_passes, "Passes per replicate, at least, whatever the budget (>= 2)")
      ->capture_default_str();
  app.add_option("--effort-floor", base.effort_floor, "The effort control's floor of q, in (0, 1]: its largest roulette weight is 1 / floor")
      ->capture_default_str();
  app.add_option("--budget", base.budget, "Seconds of passes per sampler and study, at least")->capture_default_str();
  app.add_option("--replicates", base.replicates, "Independent replicates per study (>= 3)")->capture_default_str();
  app.add_option("--margin", base.margin, "\"best\" needs the 95% interval over the runner-up above this (>= 1)")
      ->capture_default_str();
  app.add_option("--extension", base.extension, "Undecided studies go on up to this multiple of the budget (>= 1)")
      ->capture_default_str();
  app.add_option("--reference-factor", reference_factor, "Reference time (all samplers mixed) over the budget")
      ->capture_default_str();
  app.add_option("--decompose-seconds", decompose_seconds, "--decompose: seconds for the parts, per scene")
      ->capture_default_str();
  app.add_option("--step-seconds", step_seconds, "--decompose: seconds for step one versus two, per scene")
      ->capture_default_str();
  app.add_option("--width", base.width, "Image width")->capture_default_str();
  app.add_option("--height", base.height, "Image height")->capture_default_str();
  app.add_option("--vrls", base.vrls, "Light paths per pass")->capture_default_str();
  app.add_option("--seed", base.seed, "Seed of the replicates (the reference has its own)")->capture_default_str();
  app.add_option("--threads", threads, "Worker threads, the same for every sampler")->capture_default_str();
  app.add_option("--out", out, "Output folder")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (full) {
    if (app.count("--scenes") == 0) scenes.assign(vrlis::scenes::kSceneNames.begin(), vrlis::scenes::kSceneNames.end());
    if (app.count("--g") == 0) gs = {-0.9f, -0.5f, 0.f, 0.5f, 0.9f};
    if (app.count("--budget") == 0) base.budget = 12;
  }
  if (decompose && base.vrl_only) return Fail("--decompose splits the whole transport; it does not take --vrl-only");
  if (segment_scattering && !decompose) return Fail("--segment-scattering is an option of --decompose");
  if (vrl_bound && !decompose) return Fail("--vrl-bound is an option of --decompose");
  if (vrl_bound && !(*vrl_bound >= 0)) return Fail("--vrl-bound must be >= 0 (inf: no bound)");
  if (gather_weights && (decompose || base.vrl_only || full))
    return Fail("--gather-weights takes neither --decompose, --vrl-only nor --full");
  if (gather_weights && app.count("--g") > 0)
    return Fail("--gather-weights renders every scene at its default g; it does not take --g");
  if (app.count("--passes") > 0 && !gather_weights) return Fail("--passes is an option of --gather-weights");
  if (passes < 2 || passes > 100000) return Fail("--passes must be in [2, 100000]");
  if (gather_weights) {
    if (sampler_names.empty()) sampler_names = {"cauchy-sum", "auto"};
    with_effort = true;
  }
  if ((decompose || gather_weights) && app.count("--scenes") == 0)
    scenes.assign(vrlis::scenes::kSceneNames.begin(), vrlis::scenes::kSceneNames.end());

  // Every argument is checked here, before anything is written.
  for (const std::string& s : scenes)
    if (std::find(vrlis::scenes::kSceneNames.begin(), vrlis::scenes::kSceneNames.end(), s) == vrlis::scenes::kSceneNames.end())
      return Fail("unknown scene '" + s + "' (" + scene_names + ")");
  if (scenes.empty() || gs.empty()) return Fail("--scenes and --g need at least one value");
  for (float g : gs)
    if (!(g > -1 && g < 1)) return Fail("--g values must lie in (-1, 1)");
  if (!(base.budget > 0) || !(base.budget < 1e6)) return Fail("--budget must be a positive number of seconds");
  if (base.min_passes < 2) return Fail("--min-passes must be at least 2");
  if (!(base.effort_floor > 0) || !(base.effort_floor <= 1)) return Fail("--effort-floor must be in (0, 1]");
  if (!(reference_factor > 0) || !(reference_factor < 1e3)) return Fail("--reference-factor must be in (0, 1000)");
  if (!(decompose_seconds > 0) || !(step_seconds > 0) || decompose_seconds > 1e6 || step_seconds > 1e6)
    return Fail("--decompose-seconds and --step-seconds must be positive");
  if (!(base.extension >= 1) || !(base.extension < 100)) return Fail("--extension must be in [1, 100)");
  if (!(base.margin >= 1) || !(base.margin < 100)) return Fail("--margin must be in [1, 100)");
  if (base.replicates < 3 || base.replicates > 1000) return Fail("--replicates must be in [3, 1000]");
  if (base.width <= 0 || base.height <= 0 || base.width > 8192 || base.height > 8192)
    return Fail("--width and --height must be in [1, 8192]");
  if (base.vrls <= 0 || threads <= 0) return Fail("--vrls and --threads must be positive");
  if (sampler_names.empty())
    base.samplers = vrlis::compare::AllSamplers();
  for (const std::string& s : sampler_names) {
    auto m = vrlis::compare::ParseSampler(s);
    if (!m) return Fail("unknown sampler '" + s + "'");
    if (std::find(base.samplers.begin(), base.samplers.end(), *m) != base.samplers.end())
      return Fail("sampler '" + s + "' given twice");
    base.samplers.push_back(*m);
  }
  if (with_effort)
    for (std::size_t i = 0, n = base.samplers.size(); i < n; ++i)
      if (!base.samplers[i].effort) {
        vrlis::compare::Method m{base.samplers[i].sampler, true};
        if (std::find(base.samplers.begin(), base.samplers.end(), m) == base.samplers.end()) base.samplers.push_back(m);
      }
  if (!gather_weights &&
      (std::find(base.samplers.begin(), base.samplers.end(), vrlis::compare::kBaseline) == base.samplers.end() ||
       base.samplers.size() < 2))
    return Fail("--samplers must name " + SamplerName(vrlis::compare::kBaseline) + " (every ratio is to it) and at least one other");
  if (std::set<float>(gs.begin(), gs.end()).size() != gs.size() ||
      std::set<std::string>(scenes.begin(), scenes.end()).size() != scenes.size())
    return Fail("--scenes and --g must not repeat a value");
  {
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec || !vrlis::scenes::CanWrite(out + "/.probe")) return Fail("cannot write to output folder '" + out + "'");
  }
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  std::string error;

  if (decompose) {
    nlohmann::json index = nlohmann::json::array();
    std::filesystem::create_directories(out + "/decompose");
    try {
      for (const std::string& scene : scenes) {
        vrlis::compare::DecomposeConfig c;
        c.scene = scene;
        c.width = base.width;
        c.height = base.height;
        c.vrls = base.vrls;
        for (const vrlis::compare::Method& m : base.samplers)
          if (!m.effort) c.samplers.push_back(m.sampler);
        c.budget = decompose_seconds;
        c.step_budget = step_seconds;
        c.seed = base.seed;
        c.segment_scattering = segment_scattering;
        c.vrl_bound = vrl_bound;
        std::fprintf(stderr, "%s: decomposing (%.3g s parts, %.3g s steps) ...\n", scene.c_str(), c.budget,
                     c.step_budget);
        nlohmann::json j = DecompositionJson(vrlis::compare::Decompose(c));
        if (!vrlis::scenes::WriteText(out + "/decompose/" + scene + ".json", j.dump(2) + "\n", &error)) return Fail(error);
        std::printf("%s\n", j.dump().c_str());
        index.push_back(scene);
      }
    } catch (const std::exception& e) {
      return Fail(e.what());
    }
    if (!vrlis::scenes::WriteText(out + "/decompose/scenes.json", index.dump(2) + "\n", &error)) return Fail(error);
    return 0;
  }

  if (gather_weights) {
    std::vector<vrlis::compare::GatherWeightsResult> results;
    nlohmann::json rows = nlohmann::json::array();
    try {
      for (const std::string& scene : scenes)
        for (const vrlis::compare::Method& m : base.samplers) {
          vrlis::compare::GatherWeightsConfig c;
          c.scene = scene;
          c.method = m;
          c.width = base.width;
          c.height = base.height;
          c.vrls = base.vrls;
          c.passes = passes;
          c.seed = base.seed;
          c.effort_floor = base.effort_floor;
          std::fprintf(stderr, "%s %s: %d passes ...\n", scene.c_str(), SamplerName(m).c_str(), passes);
          results.push_back(vrlis::compare::MeasureGatherWeights(c));
          rows.push_back(GatherWeightsJson(results.back()));
        }
    } catch (const std::exception& e) {
      return Fail(e.what());
    }
    if (!vrlis::scenes::WriteText(out + "/gather_weights.json", rows.dump(2) + "\n", &error)) return Fail(error);
    std::printf("%s", vrlis::compare::GatherWeightsTable(results).c_str());
    return 0;
  }

  base.reference_seconds = reference_factor * base.budget;
  base.reference_dir = out + "/references";
  std::vector<StudyResult> results;
  std::string resolution;
  try {
    for (const std::string& scene : scenes)
      for (float g : gs) {
        StudyConfig c = base;
        c.scene = scene;
        c.g = g;
        std::fprintf(stderr, "%s: %zu samplers x >= %.3g s in %d replicates, reference %.3g s ...\n",
                     StudyName(c).c_str(), c.samplers.size(), c.budget, c.replicates, c.reference_seconds);
        results.push_back(vrlis::compare::RunStudy(c));
        if (!WriteStudy(results.back(), out + "/" + StudyName(c), &error)) return Fail(error);
        resolution += Resolution(results.back());
        std::fprintf(stderr, "%s", Resolution(results.back()).c_str());
      }
  } catch (const std::exception& e) {
    return Fail(e.what());
  }
  std::string table = SummaryTable(results);
  nlohmann::json all = nlohmann::json::array();
  for (const auto& r : results) all.push_back(StudyName(r.config));
  if (!vrlis::scenes::WriteText(out + "/summary.md", table, &error) ||
      !vrlis::scenes::WriteText(out + "/resolution.txt", resolution, &error) ||
      !vrlis::scenes::WriteText(out + "/studies.json", all.dump(2) + "\n", &error))
    return Fail(error);
  std::printf("%s\n%s", table.c_str(), resolution.c_str());
  return 0;
}
