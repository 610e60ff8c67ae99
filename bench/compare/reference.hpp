#pragma once
// Converged reference images, cached on disk and rebuilt when their settings change. A
// reference is a mixture: every sampler renders an equal share of its passes (with seeds no
// study uses), so no sampler is judged against its own fireflies alone.
#include <string>
#include <vector>

#include "render_call.hpp"

namespace vrlis::compare {

struct Reference {
  std::vector<double> mean;              // RGB per pixel
  std::vector<double> variance_of_mean;  // its own remaining noise, per pixel and channel
  double dof = 1;                        // that noise's degrees of freedom (NoiseDof of its passes)
  int passes = 0;
  double seconds = 0;
  bool from_cache = false;
};

// Renders about `seconds` of passes and at least `min_passes`, the samplers of `mixture` in
// turn (or loads them from `dir` when a cached render has exactly the settings described by
// `key`).
Reference GetReference(PassRenderer& renderer, const std::vector<GatherSamplers>& mixture, double seconds,
                       int min_passes, const std::string& dir, const std::string& name, const std::string& key,
                       int width, int height);

}  // namespace vrlis::compare
