#include "vrlis_integration/vpl.hpp"

#include <algorithm>

#include <vrlis/gather/surface_gather.hpp>

namespace vrlis::integration {

Spectrum GatherVpls(const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo, const std::vector<Vpl>& vpls,
                    float bound) {
  Spectrum sum;
  if (!(bound > 0)) return sum;
  const VplShareStart start{p, nf, true};
  for (const Vpl& v : vpls) {
    float g = std::min(GeometryTerm(start, v.p, v.n), bound);
    if (!(g > 0)) continue;
    float tr = scene.Connect(p, v.p);
    if (tr > 0) sum += v.flux * (g * tr);
  }
  return sum * albedo * (1 / (kPi * kPi));
}

Spectrum GatherVpls(vrlis::SegmentChoice method, const Scene& scene, const CameraSegment& seg,
                    const std::vector<Vpl>& vpls, float bound, Rng& rng) {
  Spectrum sum;
  if (!(bound > 0)) return sum;
  const HomogeneousMedium& m = scene.medium;
  const auto medium = vrlis::Medium<float>::FromAbsorptionScattering(m.g, m.sigma_a, m.sigma_s);
  // The segment as the surface gather's line: its transmittance from the line's origin is the
  // camera's from iv.a, and its phase argument -dir . w is the scattering angle's cosine
  // (light from the VPL along w, on towards the camera along -dir).
  const vrlis::VrlSegment<float> line{seg.ray(seg.iv.a), seg.ray.d, seg.iv.b - seg.iv.a};
  Rng own = rng.Split();
  for (const Vpl& v : vpls) {
    const float u = own.Uniform();
    vrlis::GatherSample<float> s = vrlis::SampleSurfaceGather(method, {v.p, v.n, line, medium}, u);
    if (!s.contributes()) continue;
    float g = GeometryTerm({s.light_point, {}, false}, v.p, v.n);
    if (!(g > 0)) continue;
    float clamp = std::min(1.f, bound / g);
    if (!scene.geometry->Occluded(s.camera_point, s.light_point)) {
      float w = s.weight * clamp;
      if (m.Bounded()) w *= scene.Transmittance(s.camera_point, s.light_point) / s.transmittance;
      sum += v.flux * w;
    }
  }
  return sum;
}

}  // namespace vrlis::integration
