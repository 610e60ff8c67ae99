#pragma once
// Where a scene's noise lives. (1) Per part of light transport (medium-to-medium,
// medium-to-surface, single scattering, direct, the path-traced remainder): its per-pass
// variance and its seconds per pass, each part rendered alone with the same seeds as the
// whole image. (2) Inside the medium-to-medium gather, on the primary camera segment of a
// grid of pixels (rays jittered as rendered): the per-pass variance of the gather as
// rendered, with step two (the camera sampler) replaced by quadrature, and with both steps
// by quadrature (what is left comes from the light paths and the pixel jitter).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render_call.hpp"

namespace vrlis::compare {

struct DecomposeConfig {
  std::string scene;
  int width = 48, height = 48;
  int vrls = 32;
  GatherSamplers sampler = kBaseline.sampler;   // the camera sampler of the parts' renders
  std::vector<GatherSamplers> samplers;  // the gathers compared in (2)
  double budget = 20;             // seconds for (1), all parts together
  double step_budget = 15;        // seconds for (2)
  int replicates = 8;             // batches for the standard errors
  int max_pixels = 48;            // (2) uses an even subset of the pixels that see the medium
  std::uint64_t seed = 1;
  // Path-traced parts estimate point-light single scattering along each segment instead of
  // jointly at the vertex before it (the variant of unbounded variance next to a light).
  bool segment_scattering = false;
  // The VRL gathers' bound on their connections (TransportSettings::vrl_bound); unset: each
  // scene's own.
  std::optional<float> vrl_bound;
};

struct Estimate {
  double value = 0, standard_error = 0;
};

struct PartResult {
  std::string name;
  Estimate variance;    // per pass, mean over pixels and channels
  double seconds = 0;   // per pass, over a pass that renders nothing
};

struct StepResult {
  GatherSamplers sampler{};
  Estimate variance;  // the gather as rendered
  Estimate step_two;  // what its step two adds: variance as rendered minus with step two by quadrature
};

struct DecomposeResult {
  DecomposeConfig config;
  float g = 0;
  int passes = 0;  // per part
  std::vector<PartResult> parts;
  Estimate total_variance;  // of the whole image (parts' covariances included)
  double total_seconds = 0, base_seconds = 0;
  int step_pixels = 0, step_passes = 0;
  Estimate paths_and_pixel_variance;  // both steps by quadrature: light paths and pixel jitter
  Estimate step_one;                  // what step one adds (step two by quadrature, minus both)
  std::vector<StepResult> gathers;
};

// Throws std::invalid_argument for an unknown scene.
DecomposeResult Decompose(const DecomposeConfig& config);

}  // namespace vrlis::compare
