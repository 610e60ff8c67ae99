#include "vrlis_integration/camera_paths.hpp"

#include <vrlis/gather/gather_vrls.hpp>

#include "vrlis_integration/direct.hpp"
#include "vrlis_integration/gather.hpp"
#include "vrlis_integration/path_tracer.hpp"
#include "vrlis_integration/work.hpp"

namespace vrlis::integration {

Spectrum VrlRadiance(const Scene& scene, const TransportSettings& tr, const std::vector<Vrl>& vrls,
                     const VplSet& vpls, Ray ray, Rng& rng, const GatherOptions& gathers) {
  const HomogeneousMedium& m = scene.medium;
  const PathTracer remainder(scene, tr);
  const vrlis::PixelEffort& effort = gathers.effort;
  // With the control on, the split sub-estimators take the price's rates and add to its records.
  const bool priced = effort.medium.on;
  const double remainder_rate = effort.split_rate(vrlis::SplitKind::Remainder, 1);
  vrlis::SplitRecord* remainder_stats = priced ? &(*effort.record)[vrlis::SplitKind::Remainder] : nullptr;
  auto vpl_connections = [&](vrlis::SplitKind kind, Spectrum beta) {
    return VplConnections{effort.split_rate(kind, tr.vpl_samples), beta, priced ? &(*effort.record)[kind] : nullptr};
  };
  // The VPLs seen from a camera segment take the medium-to-surface gather's model (theirs is a
  // point-and-line query like its; auto's rule without one); the price sets their count only.
  const vrlis::SegmentChoice vpl_sampler =
      vrlis::SegmentSamplerFor(tr.sampling.segment, vrlis::ChooseEffortModel(effort.surface, 1));
  Spectrum L, beta(1.f);
  for (int depth = 0; depth < tr.max_depth; ++depth) {
    CountVertex();
    SurfaceHit hit;
    bool found = scene.Intersect(ray, &hit);
    Interval iv = m.Clip(ray, found ? hit.t : kInfinity);
    if (!iv.Empty()) {
      CameraSegment seg{ray, iv};
      if (tr.medium_to_medium) L += beta * GatherMediumToMedium(tr.sampling, scene, seg, vrls, rng, beta, gathers);
      if (tr.direct && tr.single_scattering) L += beta * SingleScattering(tr.sampling.segment, scene, seg, rng);
      if (tr.surface_to_medium)
        L += beta * GatherVpls(vpl_sampler, scene, seg, vpls, vpl_connections(vrlis::SplitKind::VplMedium, beta),
                               tr.vpl_bound, rng);
      if (tr.indirect)  // a medium vertex by free flight, continued by path tracing
        L += SplitRemainder(remainder_rate, rng, remainder_stats, [&] {
          float d = iv.a - std::log(1 - rng.Uniform()) / m.SigmaT();
          if (!(d < iv.b)) return Spectrum();
          float u1 = rng.Uniform(), u2 = rng.Uniform();
          Ray next{ray(d), SamplePhase(m.g, ray.d, u1, u2)};
          const RemainderStart start{{next.o, {}, false}, {ray.d, m.g, false}};
          return beta * m.Albedo() * remainder.Li(next, rng, depth + 1, &start);
        });
      beta *= std::exp(-m.SigmaT() * iv.Length());  // on to the surface
    }
    if (!found) break;
    const Material& mat = scene.materials[static_cast<std::size_t>(hit.material)];
    if (mat.IsSpecular()) {
      BounceSpecular(mat, hit.p, hit.n, rng.Uniform(), &ray, &beta);
      if (depth + 1 >= tr.rr_depth) {
        float q = std::min(0.95f, beta.MaxComponent());
        if (!(rng.Uniform() < q)) break;
        beta *= 1 / q;
      }
      continue;
    }
    // The first diffuse vertex ends the camera chain.
    Vec3f nf = Dot(hit.n, ray.d) < 0 ? hit.n : -hit.n;
    if (tr.medium_to_surface && m.Present())
      L += beta * GatherMediumToSurface(tr.sampling.segment, scene, hit.p, nf, mat.albedo, vrls, rng, beta, gathers);
    if (tr.direct) L += beta * DirectSurface(scene, hit.p, nf, mat.albedo);
    if (tr.surface_to_surface)
      L += beta * GatherVpls(scene, hit.p, nf, mat.albedo, vpls, vpl_connections(vrlis::SplitKind::VplSurface, beta),
                             tr.vpl_bound, rng);
    if (tr.indirect)
      L += SplitRemainder(remainder_rate, rng, remainder_stats, [&] {
        float u1 = rng.Uniform(), u2 = rng.Uniform();
        Ray next{hit.p, SampleCosineHemisphere(nf, u1, u2)};
        const RemainderStart start{{hit.p, nf, true}, {nf, 0, true}};
        return beta * mat.albedo * remainder.Li(next, rng, depth + 1, &start);
      });
    break;
  }
  return L;
}

}  // namespace vrlis::integration
