#pragma once
// Next-event estimation at a surface: light arriving straight from every light, times
// transmittance and visibility (every light is a delta light, so each is connected once).
// In the medium, single scattering along a whole segment replaces it (gather.hpp).
#include "scene.hpp"

namespace vrlis::integration {

// Reflected radiance at a diffuse point p with normal nf (facing the viewer).
inline Spectrum DirectSurface(const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo) {
  Spectrum sum;
  auto add = [&](const std::optional<LightSample>& ls) {
    if (!ls) return;
    float cos = Dot(nf, ls->wi);
    if (!(cos > 0)) return;
    float tr = scene.Connect(p, ls->source);
    if (tr > 0) sum += ls->value * (cos / kPi * tr);
  };
  for (const PointLight& l : scene.lights.points) add(SampleLight(l, p));
  for (const CollimatedRect& l : scene.lights.rects) add(SampleLight(l, p));
  return sum * albedo;
}

}  // namespace vrlis::integration
