#pragma once
// A comparison scene ready to render, shared by the equal-time study and the noise
// decomposition: the scene by name (medium overrides applied) and the render settings at the
// run's image size and light paths per pass, with the scene's own transport.
#include <stdexcept>
#include <string>
#include <utility>

#include <vrlis_integration/renderer.hpp>
#include <vrlis_scenes/scenes.hpp>

namespace vrl_compare {

struct StudyScene {
  vrl_render::BuiltScene built;
  vrli::RenderSettings settings;
};

// Throws std::invalid_argument for an unknown scene.
inline StudyScene BuildStudyScene(const std::string& name, const vrl_render::MediumOverrides& overrides, int width,
                                  int height, int vrls) {
  auto built = vrl_render::BuildScene(name, overrides);
  if (!built) throw std::invalid_argument("unknown scene '" + name + "'");
  vrli::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.vrls_per_pass = vrls;
  settings.transport = built->transport;
  return {std::move(*built), settings};
}

}  // namespace vrl_compare
