#include "vrlis_integration/gather.hpp"

#include <vrlis/samplers/vrl_point.hpp>

namespace vrli {
namespace {

struct Sample {
  float t = 0, pdf = 0;
};

Sample SampleSegment(vrlis::Method method, const vrlis::SegmentQuery<float>& q, float u) {
  return vrlis::WithSampler(method, q, [u](const auto& sampler) {
    float t = sampler.sample(u);
    return Sample{t, sampler.pdf(t)};
  });
}

bool Usable(const Sample& s) { return s.pdf > 0 && std::isfinite(s.pdf) && std::isfinite(s.t); }

}  // namespace

Spectrum MediumToMediumIntegrand(const Scene& scene, const CameraSegment& seg, const Vrl& vrl, float v, float t) {
  const HomogeneousMedium& m = scene.medium;
  Vec3f y = vrl.origin + v * vrl.dir, x = seg.ray(t), w = y - x;
  float r2 = Dot(w, w);
  if (!(r2 > 0)) return {};
  Vec3f wh = (1 / std::sqrt(r2)) * w;  // from the camera point to the VRL point
  float tr = scene.Connect(x, y);
  if (tr == 0) return {};
  float f = m.sigma_s * m.sigma_s * Phase(m.g, Dot(seg.ray.d, wh)) * Phase(m.g, -Dot(vrl.dir, wh)) *
            std::exp(-m.SigmaT() * (t - seg.iv.a + v)) * tr / r2;
  return vrl.flux * f;
}

Spectrum GatherMediumToMedium(vrlis::Method method, const Scene& scene, const CameraSegment& seg,
                              const Vrl& vrl, Rng& rng) {
  const HomogeneousMedium& m = scene.medium;
  // Step one: a point on the VRL, near the camera line.
  vrlis::VrlPoint<float> vp({vrl.origin, vrl.dir, 0, vrl.length, seg.ray.o, seg.ray.d});
  float v = vp.sample(rng.Uniform()), pv = vp.pdf(v);
  if (!(pv > 0) || !std::isfinite(pv)) return {};
  Vec3f y = vrl.origin + v * vrl.dir;
  // Step two: a point on the camera segment, seen from y.
  vrlis::SegmentQuery<float> q =
      vrlis::MediumToMediumQuery(seg.ray.o, seg.ray.d, seg.iv.a, seg.iv.b, y, vrl.dir, m.g, m.SigmaT());
  Sample s = SampleSegment(method, q, rng.Uniform());
  if (!Usable(s)) return {};
  return MediumToMediumIntegrand(scene, seg, vrl, v, s.t) * (1 / (s.pdf * pv));
}

Spectrum GatherMediumToSurface(vrlis::Method method, const Scene& scene, Vec3f p, Vec3f nf, Spectrum albedo,
                               const Vrl& vrl, Rng& rng) {
  const HomogeneousMedium& m = scene.medium;
  // The VRL is the segment; the surface point sees it through its clamped cosine.
  vrlis::SegmentQuery<float> q;
  q.origin = vrl.origin;
  q.dir = vrl.dir;
  q.tmin = 0;
  q.tmax = vrl.length;
  q.g = m.g;
  q.point = p;
  q.lobe = {vrlis::LobeKind::ClampedCosine, nf, 0};
  q.sigma_t = m.SigmaT();
  Sample s = SampleSegment(method, q, rng.Uniform());
  if (!Usable(s)) return {};
  Vec3f y = vrl.origin + s.t * vrl.dir, w = y - p;
  float r2 = Dot(w, w);
  if (!(r2 > 0)) return {};
  Vec3f wh = (1 / std::sqrt(r2)) * w;  // from the surface point to the VRL point
  float cos = Dot(nf, wh);
  if (!(cos > 0)) return {};
  float tr = scene.Connect(p, y);
  if (tr == 0) return {};
  float f = m.sigma_s * Phase(m.g, -Dot(vrl.dir, wh)) * cos / kPi * std::exp(-m.SigmaT() * s.t) * tr / r2;
  return vrl.flux * albedo * (f / s.pdf);
}

Spectrum SingleScattering(vrlis::Method method, const Scene& scene, const CameraSegment& seg, Rng& rng) {
  const HomogeneousMedium& m = scene.medium;
  Spectrum sum;
  for (const PointLight& l : scene.lights.points) {
    if (l.fibonacci_beams) continue;  // delta directions: a camera ray never meets a beam
    vrlis::SegmentQuery<float> q;
    q.origin = seg.ray.o;
    q.dir = seg.ray.d;
    q.tmin = seg.iv.a;
    q.tmax = seg.iv.b;
    q.g = m.g;
    q.point = l.position;
    q.lobe = {vrlis::LobeKind::None, {}, 0};
    q.sigma_t = m.SigmaT();
    Sample s = SampleSegment(method, q, rng.Uniform());
    if (!Usable(s)) continue;
    Vec3f x = seg.ray(s.t);
    std::optional<LightSample> ls = SampleLight(l, x);
    if (!ls) continue;
    float tr = scene.Connect(x, ls->source);
    if (tr == 0) continue;
    float f = m.sigma_s * Phase(m.g, Dot(ls->wi, seg.ray.d)) * std::exp(-m.SigmaT() * (s.t - seg.iv.a)) * tr;
    sum += ls->value * (f / s.pdf);
  }
  if (!scene.lights.rects.empty() && std::isfinite(seg.iv.b)) {
    // Collimated beams: one distance, uniform on the segment, shared by all of them.
    float u = seg.iv.a + rng.Uniform() * seg.iv.Length();
    Vec3f x = seg.ray(u);
    float w = m.sigma_s * std::exp(-m.SigmaT() * (u - seg.iv.a)) * seg.iv.Length();
    for (const CollimatedRect& l : scene.lights.rects) {
      std::optional<LightSample> ls = SampleLight(l, x);
      if (!ls) continue;
      float tr = scene.Connect(x, ls->source);
      if (tr > 0) sum += ls->value * (w * Phase(m.g, Dot(ls->wi, seg.ray.d)) * tr);
    }
  }
  return sum;
}

}  // namespace vrli
