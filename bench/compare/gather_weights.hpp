#pragma once
// The tails of the VRL gather samples' weights on real renders (docs/stability.md): a scene at
// its default g rendered for a number of passes by one method (a sampler, the effort control
// off or on), every gather sample it takes after the passes that teach the control its first
// price (EffortPrice::kMinPasses) recorded (vrlis_integration/weight_log.hpp). Mean
// relative variance hides tails, and roulette raises them: the largest effort weight 1 / q
// (at most 1 / floor), the samples whose weights are not finite, and the samples'
// contributions to their pixel over the image's mean pixel value, the largest and a high
// quantile. Over the image's mean, not each pixel's: a sample is part of its own pixel's mean,
// so over that it could never exceed the number of passes.
#include <cstdint>
#include <string>
#include <vector>

#include "render_call.hpp"

namespace vrlis::compare {

struct GatherWeightsConfig {
  std::string scene;
  Method method{};
  int width = 48, height = 48;
  int vrls = 32;    // light paths per pass
  int passes = 40;  // the effort control decides from the second on: at least 2
  std::uint64_t seed = 1;
  double effort_floor = vrlis::EffortSettings{}.floor;
};

inline constexpr double kGatherWeightsQuantile = 0.999;

struct GatherWeightsResult {
  GatherWeightsConfig config;
  float g = 0;
  std::uint64_t samples = 0, non_finite = 0;
  double largest_effort_weight = 0;
  double mean_pixel = 0;  // over pixels and all passes, of a pass's pixel value (RMS of RGB)
  // A sample's contribution to its pixel over mean_pixel: the largest, the kGatherWeightsQuantile quantile.
  double largest_contribution = 0, quantile_contribution = 0;
  double seconds = 0;  // of the passes
};

// Throws std::invalid_argument for an unknown scene.
GatherWeightsResult MeasureGatherWeights(const GatherWeightsConfig& config);

// The Markdown table of the results, one row each.
std::string GatherWeightsTable(const std::vector<GatherWeightsResult>& results);

}  // namespace vrlis::compare
