#pragma once
// Converged reference images, cached on disk and rebuilt when their settings change.
#include <string>
#include <vector>

#include <vrlis_integration/renderer.hpp>

namespace vrl_compare {

struct Reference {
  std::vector<double> mean;               // RGB per pixel
  std::vector<double> variance_of_mean;   // its own remaining noise, per pixel and channel
  int passes = 0;
  double seconds = 0;
  bool from_cache = false;
};

// Renders `seconds` of passes with `renderer` (or loads them from `dir` when a cached render
// has exactly the settings described by `key`).
Reference GetReference(vrli::Renderer& renderer, double seconds, const std::string& dir,
                       const std::string& name, const std::string& key, int width, int height);

}  // namespace vrl_compare
