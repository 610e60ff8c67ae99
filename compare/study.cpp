#include "study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <vrlis_integration/renderer.hpp>
#include <vrlis_scenes/scenes.hpp>

#include "image_stats.hpp"
#include "reference.hpp"

namespace vrl_compare {

double Rmse(const std::vector<double>& image, const std::vector<double>& reference,
            const std::vector<double>& reference_variance) {
  double sum = 0;
  for (std::size_t i = 0; i < image.size(); ++i) sum += (image[i] - reference[i]) * (image[i] - reference[i]) - reference_variance[i];
  return std::sqrt(std::max(sum / static_cast<double>(image.size()), 0.0));
}

namespace {

// Everything a reference image depends on; a cached one is reused only if this matches.
std::string ReferenceKey(const StudyConfig& c, const vrli::TransportSettings& t) {
  std::ostringstream key;
  key << "v1 scene=" << c.scene << " g=" << c.g << " size=" << c.width << "x" << c.height << " vrls=" << c.vrls
      << " method=" << vrlis::Name(c.reference_method) << " seconds=" << c.reference_seconds
      << " transport=" << t.medium_to_medium << t.medium_to_surface << t.direct << t.indirect << t.light_caustics
      << t.first_segment_only << "/" << t.max_depth << "/" << t.rr_depth;
  return key.str();
}

// log-log interpolation of the error curve at exactly `budget` seconds.
double ErrorAtBudget(const std::vector<Checkpoint>& curve, double budget) {
  auto after = std::find_if(curve.begin(), curve.end(), [&](const Checkpoint& c) { return c.seconds >= budget; });
  if (after == curve.end()) return curve.back().rmse;
  if (after == curve.begin() || after->rmse <= 0 || std::prev(after)->rmse <= 0) return after->rmse;
  const Checkpoint& a = *std::prev(after);
  double s = std::log(budget / a.seconds) / std::log(after->seconds / a.seconds);
  return a.rmse * std::pow(after->rmse / a.rmse, s);
}

struct Runner {
  vrlis::Method method;
  std::uint64_t seed;
  PassStatistics stats;
  double seconds = 0;
  MethodResult result;
};

}  // namespace

StudyResult RunStudy(const StudyConfig& config) {
  vrl_render::MediumOverrides overrides;
  overrides.g = config.g;
  auto built = vrl_render::BuildScene(config.scene, overrides);
  if (!built) throw std::invalid_argument("unknown scene '" + config.scene + "'");
  vrli::RenderSettings settings;
  settings.width = config.width;
  settings.height = config.height;
  settings.vrls_per_pass = config.vrls;
  settings.transport = built->transport;
  // One renderer per camera sampler: the sampling method is part of the render settings.
  auto renderer_for = [&](vrlis::Method m) {
    vrli::RenderSettings s = settings;
    s.transport.sampling = {m, {}};
    return vrli::VrlRenderer(built->scene, s);
  };
  vrli::VrlRenderer reference_renderer = renderer_for(config.reference_method);

  std::ostringstream name;
  name << config.scene << "_g" << config.g;
  Reference reference = GetReference(reference_renderer, config.reference_seconds, config.reference_dir,
                                     name.str(), ReferenceKey(config, settings.transport), config.width, config.height);

  std::vector<Runner> runners;
  for (std::size_t i = 0; i < config.methods.size(); ++i)
    runners.push_back({config.methods[i], vrli::SplitMix64(config.seed * 1000003 + i),
                       PassStatistics(config.width, config.height), 0, {}});

  // The method that has spent the least time renders next, so that a noisy machine slows
  // all of them alike and every curve covers the same stretch of wall time.
  while (true) {
    auto next = std::min_element(runners.begin(), runners.end(),
                                 [](const Runner& a, const Runner& b) { return a.seconds < b.seconds; });
    if (next->seconds >= config.budget) break;
    vrli::PassStats pass_stats;
    auto start = std::chrono::steady_clock::now();
    vrli::Film pass = renderer_for(next->method).RenderPass(next->seed, static_cast<std::uint64_t>(next->stats.passes()), &pass_stats);
    next->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    next->stats.Add(pass);
    next->result.curve.push_back({next->seconds, next->stats.passes(),
                                  Rmse(next->stats.Mean(), reference.mean, reference.variance_of_mean)});
  }

  StudyResult out;
  out.config = config;
  out.reference_passes = reference.passes;
  out.reference_seconds = reference.seconds;
  out.reference_cached = reference.from_cache;
  double noise = 0;
  for (double v : reference.variance_of_mean) noise += v;
  out.reference_noise_rmse = std::sqrt(noise / static_cast<double>(reference.variance_of_mean.size()));
  for (Runner& r : runners) {
    r.result.method = r.method;
    r.result.rmse_at_budget = ErrorAtBudget(r.result.curve, config.budget);
    r.result.image = r.stats.Mean();
    out.methods.push_back(std::move(r.result));
  }
  out.reference_image = std::move(reference.mean);
  return out;
}

}  // namespace vrl_compare
