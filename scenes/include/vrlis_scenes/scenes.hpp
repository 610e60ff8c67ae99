#pragma once
// The comparison scenes of docs/scenes.md, built on Embree (a private detail of this target).
#include <array>
#include <optional>
#include <string_view>

#include <vrlis_integration/scene.hpp>
#include <vrlis_integration/transport.hpp>

namespace vrlis::scenes {

inline constexpr std::array<std::string_view, 6> kSceneNames = {"bidirectional", "room", "cube", "corner", "cloud", "fog"};

// Overrides of a scene's medium.
struct MediumOverrides {
  std::optional<float> g, sigma_s, sigma_a;
};

struct BuiltScene {
  vrlis::integration::Scene scene;
  vrlis::integration::TransportSettings transport;  // what the scene renders by default
  bool has_surfaces = true;           // false: nothing for a medium-to-surface gather to land on
};

// Empty for an unknown name.
std::optional<BuiltScene> BuildScene(std::string_view name, const MediumOverrides& overrides);

}  // namespace vrlis::scenes
