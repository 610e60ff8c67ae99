#pragma once
// One study of a scene at one g: every sampler renders the same passes (the same light
// paths and pixel streams: a paired comparison) in R independent replicates with their own
// seeds, interleaved pass by pass in a rotating order so that a noisy machine slows all of
// them alike. Per sampler: seconds per pass, per-pass variance (from the passes themselves),
// efficiency 1 / (variance x seconds), its ratio to Novák's with a 95% interval, and the
// error against a mixture reference as the check that nothing is biased.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "efficiency.hpp"
#include "error_to_noise.hpp"
#include "render_call.hpp"

namespace vrlis::compare {

struct StudyConfig {
  std::string scene;
  float g = 0;
  int width = 48, height = 48;
  int vrls = 32;                  // light paths per pass
  double budget = 8;              // seconds per sampler, at least
  // Passes per replicate, at least, whatever the budget: two for a variance within each; the
  // effort control decides from its second pass on a price that settles over the next few, so
  // where passes are long its study asks for more.
  int min_passes = 2;
  int replicates = 12;
  // "best" needs the interval against the runner-up above this: the interval sees the spread
  // between replicates, not the drift of a shared machine's timings from one run to the next.
  double margin = 1.05;
  // A study whose winner's interval against the runner-up still holds the margin goes on,
  // up to this multiple of the budget.
  double extension = 2;
  double reference_seconds = 15;  // for the mixture reference, all samplers together
  std::vector<Method> samplers;  // includes kBaseline
  std::uint64_t seed = 1;
  std::string reference_dir;      // shared cache of references
  // The image of the two VRL gathers alone (medium-to-medium and medium-to-surface), as the
  // thesis and Novák et al. 2012 measure, instead of the scene's whole transport.
  bool vrl_only = false;
  // The effort control's floor of q for the methods with it on (vrlis::EffortSettings::floor).
  double effort_floor = vrlis::EffortSettings{}.floor;
};

// How one replicate converged: after each of its passes, the seconds spent so far and the
// RMSE of its running mean against the reference.
struct Progression {
  std::vector<double> seconds, rmse;
};

struct SamplerResult {
  Method sampler{};
  int passes = 0;  // over all replicates
  Replicates replicates;
  double variance = 0, seconds = 0, efficiency = 0;  // pooled over the replicates
  RatioInterval to_baseline;                         // efficiency / the baseline's
  RatioInterval to_best_published;                   // efficiency / the study's best fixed published method's
  // Efficiency over the same sampler's without the effort control (with the control on, and
  // that sampler in the study, only).
  std::optional<RatioInterval> to_without_effort;
  // Squared error against the reference over the noise expected of both images, and the
  // range it keeps when unbiased (error_to_noise.hpp).
  ErrorToNoise error_to_noise;
  std::string verdict;  // "best", "tie" or empty
  std::vector<double> image;
  std::vector<Progression> progression;  // per replicate
};

struct StudyResult {
  StudyConfig config;
  std::vector<SamplerResult> samplers;
  int passes_per_replicate = 0;
  std::string verdict;            // "best" or "tie"
  RatioInterval top_vs_runner_up;  // efficiency of the most efficient over the next
  Method best_published{};         // the most efficient fixed published method (IsFixedPublished)
  double resolution = 0;          // median over samplers of (interval high / point) against the baseline
  std::vector<double> reference_image;
  int reference_passes = 0;
  double reference_seconds = 0;
  bool reference_cached = false;
  double reference_noise = 0;  // mean over pixels of the reference's variance of the mean
  double reference_dof = 1;    // its noise's degrees of freedom (NoiseDof)
  double sampler_noise = 0;    // the same for the samplers' images, averaged over samplers
};

// Throws std::invalid_argument for an unknown scene.
StudyResult RunStudy(const StudyConfig& config);

}  // namespace vrlis::compare
