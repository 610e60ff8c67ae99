#pragma once
// A virtual ray light: one segment of a light path inside the medium, y(v) = origin + v
// dir, v in [0, length], carrying the flux the light path had when it entered the segment.
// Transmittance along the VRL is not in the flux: the gathers apply T(v).
#include "common.hpp"

namespace vrlis::integration {

struct Vrl {
  Vec3f origin{}, dir{};
  float length = 0;
  Spectrum flux{};
};

}  // namespace vrlis::integration
