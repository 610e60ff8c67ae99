#include "vrlis_integration/vpl.hpp"

#include <algorithm>
#include <cmath>

#include <vrlis/effort/work.hpp>
#include <vrlis/gather/surface_gather.hpp>

namespace vrlis::integration {

namespace {
std::vector<double> Fluxes(const std::vector<Vpl>& vpls) {
  std::vector<double> flux(vpls.size());
  for (std::size_t i = 0; i < vpls.size(); ++i) flux[i] = vpls[i].flux.Average();
  return flux;
}
}  // namespace

VplSet::VplSet(std::vector<Vpl> vpls) : vpls_(std::move(vpls)), choice_(Fluxes(vpls_)) {}

Spectrum GatherVpls(const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo, const VplSet& vpls,
                    const VplConnections& connections, float bound, Rng& rng) {
  if (!(bound > 0) || vpls.empty()) return {};
  const ConnectionEnd start{p, nf, true};
  Rng own = rng.Split();
  return SplitConnections(connections, albedo * (1 / (kPi * kPi)), own, [&] {
    const auto [v, pick] = vpls.Sample(own.Uniform());
    const float g = std::min(GeometryTerm(start, {v->p, v->n, true}), bound);  // g x GatherShare(g, bound)
    if (!(g > 0)) return Spectrum();
    const float tr = scene.Connect(p, v->p);
    return tr > 0 ? v->flux * (g * tr / pick) : Spectrum();
  });
}

Spectrum GatherVpls(vrlis::SegmentChoice method, const Scene& scene, const CameraSegment& seg, const VplSet& vpls,
                    const VplConnections& connections, float bound, Rng& rng) {
  if (!(bound > 0) || vpls.empty()) return {};
  const vrlis::Medium<float> medium = MediumOf(scene.medium);
  // The segment as the surface gather's line: its transmittance from the line's origin is the
  // camera's from iv.a, and its phase argument -dir . w is the scattering angle's cosine
  // (light from the VPL along w, on towards the camera along -dir).
  const vrlis::VrlSegment<float> line{seg.ray(seg.iv.a), seg.ray.d, seg.iv.b - seg.iv.a};
  Rng own = rng.Split();
  const double sample_work = vrlis::LanesWork().SurfaceSample(method);  // the library's sample, one at a time
  return SplitConnections(connections, Spectrum(1.f), own, [&] {
    ThreadWork() += sample_work;
    const float u_vpl = own.Uniform(), u = own.Uniform();
    const auto [v, pick] = vpls.Sample(u_vpl);
    vrlis::GatherSample<float> s = vrlis::SampleSurfaceGather(method, {v->p, v->n, line, medium}, u);
    float g = GeometryTerm({s.light_point, {}, false}, {v->p, v->n, true});
    if (!s.contributes() || !(g > 0)) return Spectrum();
    return v->flux * (Connect(scene, s) * GatherShare(g, bound) / pick);
  });
}

}  // namespace vrlis::integration
