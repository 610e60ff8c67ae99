#pragma once
// A comparison scene ready to render, shared by the equal-time study and the noise
// decomposition: the scene by name (medium overrides applied) and the render settings at the
// run's image size and light paths per pass, with the scene's own transport.
#include <stdexcept>
#include <string>
#include <utility>

#include <vrlis_integration/renderer.hpp>
#include <vrlis_scenes/scenes.hpp>

namespace vrlis::compare {

struct StudyScene {
  vrlis::scenes::BuiltScene built;
  vrlis::integration::RenderSettings settings;
};

// Throws std::invalid_argument for an unknown scene.
inline StudyScene BuildStudyScene(const std::string& name, const vrlis::scenes::MediumOverrides& overrides, int width,
                                  int height, int vrls) {
  auto built = vrlis::scenes::BuildScene(name, overrides);
  if (!built) throw std::invalid_argument("unknown scene '" + name + "'");
  vrlis::integration::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.vrls_per_pass = vrls;
  settings.transport = built->transport;
  return {std::move(*built), settings};
}

// Only the two VRL gathers, whole: no direct lighting, single scattering, VPLs or path-traced
// remainder, which would take a share of their connections.
inline void KeepVrlGathersOnly(StudyScene& s) {
  vrlis::integration::TransportSettings& t = s.settings.transport;
  t.direct = t.single_scattering = t.indirect = false;
  t.vrl_bound = vrlis::integration::kUnbounded;
  t.surface_to_surface = t.surface_to_medium = false;
  t.medium_to_medium = true;
  t.medium_to_surface = s.built.has_surfaces;
}

}  // namespace vrlis::compare
