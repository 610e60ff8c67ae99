// vrl_compare: renders each scene and g with every camera sampler for the same wall-clock
// budget, interleaved, and scores the images against converged references. Writes, under
// --out: one folder per study (error curve CSV, equal-time images, result JSON) and a
// summary table (Markdown and JSON), which it also prints.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include <vrlis_scenes/image_io.hpp>

#include "image_stats.hpp"
#include "study.hpp"

namespace {

using vrl_compare::StudyConfig;
using vrl_compare::StudyResult;

int Fail(const std::string& message) {
  std::fprintf(stderr, "vrl_compare: %s\n", message.c_str());
  return 2;
}

std::string StudyName(const StudyConfig& c) {
  std::ostringstream s;
  s << c.scene << "_g" << c.g;
  return s.str();
}

void WriteStudy(const StudyResult& r) {
  const StudyConfig& c = r.config;
  std::filesystem::create_directories(c.out_dir);
  std::ostringstream csv;
  csv << "method,seconds,passes,rmse\n";
  nlohmann::json methods = nlohmann::json::array();
  vrli::Film reference = vrl_compare::ToFilm(r.reference_image, c.width, c.height);
  float exposure = vrl_render::AutoExposure(reference);
  std::string error;
  for (const auto& m : r.methods) {
    for (const auto& p : m.curve) csv << vrlis::Name(m.method) << "," << p.seconds << "," << p.passes << "," << p.rmse << "\n";
    const auto& last = m.curve.back();
    methods.push_back({{"method", vrlis::Name(m.method)}, {"passes", last.passes}, {"seconds", last.seconds},
                       {"rmse_at_budget", m.rmse_at_budget}});
    vrl_render::WritePng(c.out_dir + "/" + std::string(vrlis::Name(m.method)) + ".png",
                         vrl_compare::ToFilm(m.image, c.width, c.height), exposure, &error);
  }
  vrl_render::WritePng(c.out_dir + "/reference.png", reference, exposure, &error);
  vrl_render::WriteText(c.out_dir + "/curve.csv", csv.str(), &error);
  nlohmann::json j = {{"scene", c.scene}, {"g", c.g}, {"width", c.width}, {"height", c.height}, {"vrls", c.vrls},
                      {"budget", c.budget}, {"methods", methods},
                      {"reference", {{"method", vrlis::Name(c.reference_method)}, {"passes", r.reference_passes},
                                     {"seconds", r.reference_seconds}, {"cached", r.reference_cached},
                                     {"noise_rmse", r.reference_noise_rmse}}}};
  vrl_render::WriteText(c.out_dir + "/result.json", j.dump(2) + "\n", &error);
}

// One row per study and method: RMSE at the budget, MSE relative to Novak's, the winner.
std::string SummaryTable(const std::vector<StudyResult>& results) {
  std::ostringstream t;
  t << "| scene | g | method | passes | RMSE at budget | MSE / MSE Novak | |\n|---|---|---|---|---|---|---|\n";
  for (const auto& r : results) {
    double novak = 0, best = 1e300;
    for (const auto& m : r.methods) {
      if (m.method == vrlis::CameraSamplers::Of<vrlis::NovakEntry>()) novak = m.rmse_at_budget;
      best = std::min(best, m.rmse_at_budget);
    }
    for (const auto& m : r.methods) {
      char line[256];
      double ratio = novak > 0 ? (m.rmse_at_budget * m.rmse_at_budget) / (novak * novak) : 0;
      std::snprintf(line, sizeof line, "| %s | %g | %s | %d | %.4g | %.3f | %s |\n", r.config.scene.c_str(), r.config.g,
                    std::string(vrlis::Name(m.method)).c_str(), m.curve.back().passes, m.rmse_at_budget, ratio,
                    m.rmse_at_budget == best ? "best" : "");
      t << line;
    }
  }
  return t.str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Equal-time comparison of the vrlis camera samplers on the seed's scenes."};
  std::vector<std::string> scenes = {"bidirectional", "room"};
  std::vector<float> gs = {-0.9f, 0.5f, 0.9f};
  std::vector<std::string> samplers;
  bool full = false;
  StudyConfig base;
  double reference_factor = 6;
  int threads = 2;
  std::string out = "out/compare";
  app.add_flag("--full", full, "Every scene, g in {-0.9,-0.5,0,0.5,0.9}, 4x the budget, 96x96");
  app.add_option("--scenes", scenes, "Scenes (bidirectional, room, cube, corner)")->delimiter(',')->capture_default_str();
  app.add_option("--g", gs, "Henyey-Greenstein g values, each in (-1, 1)")->delimiter(',')->capture_default_str();
  app.add_option("--samplers", samplers, "Camera samplers (default: all the library offers)")->delimiter(',');
  app.add_option("--budget", base.budget, "Wall-clock seconds per sampler and study")->capture_default_str();
  app.add_option("--reference-factor", reference_factor, "Reference time as a multiple of the budget")->capture_default_str();
  app.add_option("--width", base.width, "Image width")->capture_default_str();
  app.add_option("--height", base.height, "Image height")->capture_default_str();
  app.add_option("--vrls", base.vrls, "Light paths per pass")->capture_default_str();
  app.add_option("--seed", base.seed, "Seed (each sampler derives its own)")->capture_default_str();
  app.add_option("--threads", threads, "Worker threads, the same for every sampler")->capture_default_str();
  app.add_option("--out", out, "Output folder")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (full) {
    if (app.count("--scenes") == 0) scenes = {"bidirectional", "room", "cube", "corner"};
    if (app.count("--g") == 0) gs = {-0.9f, -0.5f, 0.f, 0.5f, 0.9f};
    if (app.count("--budget") == 0) base.budget *= 4;
    if (app.count("--width") == 0) base.width = 96;
    if (app.count("--height") == 0) base.height = 96;
  }
  for (float g : gs)
    if (!(g > -1 && g < 1)) return Fail("--g values must lie in (-1, 1)");
  if (!(base.budget > 0) || !(reference_factor >= 1)) return Fail("--budget must be > 0 and --reference-factor >= 1");
  if (base.width <= 0 || base.height <= 0 || base.vrls <= 0 || threads <= 0)
    return Fail("--width, --height, --vrls and --threads must be positive");
  if (samplers.empty())
    for (vrlis::Method m : vrlis::kMethods) base.methods.push_back(m);
  for (const std::string& s : samplers) {
    auto m = vrlis::ParseMethod(s);
    if (!m) return Fail("unknown sampler '" + s + "'");
    base.methods.push_back(*m);
  }
  if (!vrl_render::CanWrite(out + "/.probe")) {
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec || !vrl_render::CanWrite(out + "/.probe")) return Fail("cannot write to output folder '" + out + "'");
  }
  base.reference_seconds = reference_factor * base.budget;
  base.reference_dir = out + "/references";
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  std::vector<StudyResult> results;
  try {
    for (const std::string& scene : scenes)
      for (float g : gs) {
        StudyConfig c = base;
        c.scene = scene;
        c.g = g;
        c.out_dir = out + "/" + StudyName(c);
        std::fprintf(stderr, "%s: %zu samplers x %.3g s, reference %.3g s ...\n", StudyName(c).c_str(), c.methods.size(),
                     c.budget, c.reference_seconds);
        results.push_back(vrl_compare::RunStudy(c));
        WriteStudy(results.back());
      }
  } catch (const std::exception& e) {
    return Fail(e.what());
  }
  std::string table = SummaryTable(results);
  std::string error;
  vrl_render::WriteText(out + "/summary.md", table, &error);
  nlohmann::json all = nlohmann::json::array();
  for (const auto& r : results) all.push_back(StudyName(r.config));
  vrl_render::WriteText(out + "/studies.json", all.dump(2) + "\n", &error);
  std::printf("%s", table.c_str());
  return 0;
}
