#pragma once
// Surface materials: what the scenes use and nothing more.
#include "common.hpp"

namespace vrlis::integration {

enum class MaterialKind { Diffuse, Mirror, Glass };

struct Material {
  MaterialKind kind = MaterialKind::Diffuse;
  Spectrum albedo{0.5f};  // diffuse reflectance, or the specular tint
  float ior = 1.5f;       // Glass only

  bool IsSpecular() const { return kind != MaterialKind::Diffuse; }
};

// Dielectric Fresnel reflectance for unpolarised light; cos_i > 0 on the side of eta_i.
inline float FresnelDielectric(float cos_i, float eta_i, float eta_t) {
  float sin_t = eta_i / eta_t * std::sqrt(std::max(0.f, 1 - cos_i * cos_i));
  if (sin_t >= 1) return 1;
  float cos_t = std::sqrt(std::max(0.f, 1 - sin_t * sin_t));
  float rs = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
  float rp = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
  return (rs * rs + rp * rp) / 2;
}

// A specular bounce of a ray travelling along d at a surface with normal n (either side):
// the new direction and the weight f cos / pdf. Glass picks reflection with probability F.
inline Vec3f SampleSpecular(const Material& m, Vec3f d, Vec3f n, float u, Spectrum* weight) {
  float cos_i = -Dot(d, n);
  Vec3f nf = cos_i >= 0 ? n : -n;  // facing the incoming ray
  cos_i = std::abs(cos_i);
  Vec3f reflected = d + (2 * cos_i) * nf;
  *weight = m.albedo;
  if (m.kind == MaterialKind::Mirror) return reflected;
  bool entering = Dot(d, n) < 0;  // n points out of the glass
  float eta_i = entering ? 1.f : m.ior, eta_t = entering ? m.ior : 1.f;
  float f = FresnelDielectric(cos_i, eta_i, eta_t);
  if (u < f) return reflected;
  float eta = eta_i / eta_t;
  float cos_t = std::sqrt(std::max(0.f, 1 - eta * eta * (1 - cos_i * cos_i)));
  // Radiance is scaled by (eta_t/eta_i)^2 across the interface; for a camera path (which
  // carries importance) the factor is the inverse. Both cancel for a closed glass object
  // entered and left once, so we keep the symmetric form and apply no factor.
  return Normalize(eta * d + (eta * cos_i - cos_t) * nf);
}

// A path's specular bounce at point p: the ray leaves p in the sampled direction and the
// throughput takes the bounce's weight.
inline void BounceSpecular(const Material& m, Vec3f p, Vec3f n, float u, Ray* ray, Spectrum* beta) {
  Spectrum w;
  Vec3f d = SampleSpecular(m, ray->d, n, u, &w);
  *beta *= w;
  *ray = {p, d};
}

}  // namespace vrlis::integration
