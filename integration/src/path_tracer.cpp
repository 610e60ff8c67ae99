#include "vrlis_integration/path_tracer.hpp"

#include "vrlis_integration/direct.hpp"
#include "vrlis_integration/gather.hpp"
#include "vrlis_integration/work.hpp"

namespace vrlis::integration {
namespace {
constexpr vrlis::SegmentChoice kEquiangular = vrlis::SegmentSamplers::Of<vrlis::EquiangularEntry>();
}  // namespace

Spectrum PathTracer::Li(Ray ray, Rng& rng, int depth, const RemainderStart* start) const {
  const HomogeneousMedium& m = scene_.medium;
  Spectrum L, beta(1.f);
  bool after_vertex = false;  // the ray leaves a vertex that gathered with VertexSingleScattering
  auto at_vertex = [&](Vec3f p, VertexLobe lobe, const MediumShare* share) {
    after_vertex = tr_.vertex_single_scattering;
    if (after_vertex) L += beta * VertexSingleScattering(scene_, p, lobe, rng, share);
  };
  // The start's connections to medium points that the VRL gathers left to the path.
  const bool medium_shared = start && tr_.vrl_bound < kUnbounded;
  const MediumShare medium_share = start ? MediumShare{start->from, tr_.vrl_bound} : MediumShare{};
  if (medium_shared) at_vertex(start->from.p, start->lobe, &medium_share);
  for (bool first = true; depth < tr_.max_depth; ++depth, first = false) {
    CountVertex();
    const RemainderStart* shared_from = first ? start : nullptr;
    SurfaceHit hit;
    bool found = scene_.Intersect(ray, &hit);
    Interval iv = m.Clip(ray, found ? hit.t : kInfinity);
    bool scattered = false;
    if (!iv.Empty()) {
      if (shared_from && !medium_shared) {
        beta *= std::exp(-m.SigmaT() * iv.Length());
      } else {
        const MediumShare* share = shared_from ? &medium_share : nullptr;
        // Light scattered once on this segment, estimated over the whole segment: a point light
        // seen from a free-flight vertex would weigh I / r^2, of infinite variance next to the
        // light, while equiangular sampling cancels the 1 / r^2 (Kulla and Fajardo 2012).
        L += beta * SingleScattering(kEquiangular, scene_, CameraSegment{ray, iv}, rng, after_vertex, share);
        float d = iv.a - std::log(1 - rng.Uniform()) / m.SigmaT();
        if (d < iv.b) {  // a medium vertex: the path goes on from it
          Vec3f p = ray(d);
          if (share) {
            const float w = (*share)(p);
            if (!(w > 0)) break;  // the VRL gathers carry this connection whole
            beta *= w;
          }
          beta *= m.Albedo();
          at_vertex(p, {ray.d, m.g, false}, nullptr);
          float u1 = rng.Uniform(), u2 = rng.Uniform();
          ray = {p, SamplePhase(m.g, ray.d, u1, u2)};
          scattered = true;
        }
      }
    }
    if (!scattered) {
      if (!found) break;  // no emitter is ever seen directly: all lights are delta lights
      const Material& mat = scene_.materials[static_cast<std::size_t>(hit.material)];
      if (mat.IsSpecular()) {
        BounceSpecular(mat, hit.p, hit.n, rng.Uniform(), &ray, &beta);
        after_vertex = false;  // a delta direction: nothing to gather jointly
      } else {
        Vec3f nf = Dot(hit.n, ray.d) < 0 ? hit.n : -hit.n;
        if (shared_from) {
          float share = RemainderShare(GeometryTerm(shared_from->from, {hit.p, nf, true}), tr_.vpl_bound);
          if (!(share > 0)) break;  // the VPLs carry this connection whole
          beta *= share;
        }
        L += beta * DirectSurface(scene_, hit.p, nf, mat.albedo);
        beta *= mat.albedo;
        at_vertex(hit.p, {nf, 0, true}, nullptr);
        float u1 = rng.Uniform(), u2 = rng.Uniform();
        ray = {hit.p, SampleCosineHemisphere(nf, u1, u2)};
      }
    }
    if (depth + 1 >= tr_.rr_depth) {
      float q = std::min(0.95f, beta.MaxComponent());
      if (!(rng.Uniform() < q)) break;
      beta *= 1 / q;
    }
  }
  return L;
}

}  // namespace vrlis::integration
