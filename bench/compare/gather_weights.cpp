#include "gather_weights.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <vrlis_integration/weight_log.hpp>

#include "study_scene.hpp"

namespace vrlis::compare {

GatherWeightsResult MeasureGatherWeights(const GatherWeightsConfig& config) {
  StudyScene scene = BuildStudyScene(config.scene, {}, config.width, config.height, config.vrls);
  scene.settings.transport.effort.floor = config.effort_floor;
  // The passes that take every gather once, for the effort control's first price, are not
  // recorded: they would dilute what its decisions do (in room the first pass takes most samples).
  PassRenderer first(scene.built.scene, scene.settings);
  vrlis::integration::WeightLog log;
  scene.settings.transport.weight_log = &log;
  PassRenderer recorded(scene.built.scene, scene.settings);
  vrlis::EffortPrice price(config.width, config.height);
  vrlis::ScoreOctaves marginal_scores;  // which gathers VrlMarginal fits, learned like the price
  GatherWeightsResult r;
  r.config = config;
  r.g = scene.built.scene.medium.g;
  double pixel_sum = 0;
  for (int pass = 0; pass < config.passes; ++pass) {
    double seconds = 0;
    PassRenderer& renderer = pass < vrlis::EffortPrice::kMinPasses ? first : recorded;
    const vrlis::integration::Film film =
        renderer.Render(config.method, config.seed, static_cast<std::uint64_t>(pass), &seconds, &price, &marginal_scores);
    r.seconds += seconds;
    for (const vrlis::integration::Spectrum& p : film.pixels) pixel_sum += std::sqrt(p.MeanSquare());
  }
  r.mean_pixel = pixel_sum / (double(config.passes) * double(config.width) * double(config.height));
  r.samples = log.samples();
  r.non_finite = log.non_finite();
  r.largest_effort_weight = log.largest_effort_weight();
  r.largest_contribution = log.largest_contribution() / r.mean_pixel;
  r.quantile_contribution = log.Quantile(kGatherWeightsQuantile) / r.mean_pixel;
  return r;
}

std::string GatherWeightsTable(const std::vector<GatherWeightsResult>& results) {
  std::ostringstream t;
  t << "| scene | g | method | samples | largest effort weight | bound 1 / floor | non-finite | "
       "largest contribution / mean pixel | "
    << 100 * kGatherWeightsQuantile << "% quantile / mean pixel |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const GatherWeightsResult& r : results) {
    char line[384];
    std::snprintf(line, sizeof line, "| %s | %g | %s | %llu | %.3g | %.3g | %llu | %.3g | %.3g |\n",
                  r.config.scene.c_str(), r.g, SamplerName(r.config.method).c_str(),
                  static_cast<unsigned long long>(r.samples), r.largest_effort_weight, 1 / r.config.effort_floor,
                  static_cast<unsigned long long>(r.non_finite), r.largest_contribution, r.quantile_contribution);
    t << line;
  }
  return t.str();
}

}  // namespace vrlis::compare
