#include "vrlis_integration/light_paths.hpp"
#include "vrlis_integration/work.hpp"

#include <tbb/parallel_for.h>

namespace vrlis::integration {
namespace {

struct Emission {
  Ray ray;
  Spectrum flux;
};

// The rotation of each point light's lattice in this pass (identity where it is fixed).
using LatticeRotations = std::vector<Rotation>;

Emission SampleEmission(const Scene& scene, const LatticeRotations& rotations, int index, int count, Rng& rng) {
  std::vector<float> powers = scene.lights.Powers();
  float total = 0;
  for (float p : powers) total += p;
  // Choose a light in proportion to its power.
  float u = rng.Uniform() * total, acc = 0;
  std::size_t k = 0;
  while (k + 1 < powers.size() && u >= acc + powers[k]) acc += powers[k++];
  float pick = powers[k] / total;
  float u1 = rng.Uniform(), u2 = rng.Uniform();
  if (k < scene.lights.points.size()) {
    const PointLight& l = scene.lights.points[k];
    Vec3f d = l.fibonacci_beams ? rotations[k](FibonacciDirection(index, count))
                                : SphericalDirection(Frame(l.axis), 1 - u1 * (1 - l.cos_cone), 2 * kPi * u2);
    return {{l.position, d}, l.intensity * (l.SolidAngle() / (pick * count))};
  }
  const CollimatedRect& l = scene.lights.rects[k - scene.lights.points.size()];
  float power = l.Area() * std::abs(Dot(l.Normal(), l.direction));
  return {{l.corner + u1 * l.edge1 + u2 * l.edge2, l.direction}, l.irradiance * (power / (pick * count))};
}

void TracePath(const Scene& scene, const TransportSettings& tr, const LatticeRotations& rotations, int index,
               int count, Rng& rng, std::vector<Vrl>* out, std::vector<Vpl>* vpls) {
  Emission e = SampleEmission(scene, rotations, index, count, rng);
  Ray ray = e.ray;
  Spectrum beta = e.flux;
  const float start = e.flux.MaxComponent();
  const HomogeneousMedium& m = scene.medium;
  bool scattered = false;  // met a diffuse or medium vertex yet
  auto survives = [&](int depth) {  // Russian roulette
    if (depth + 1 < tr.rr_depth) return true;
    float q = std::min(0.95f, beta.MaxComponent() / start);
    if (!(rng.Uniform() < q)) return false;
    beta *= 1 / q;
    return true;
  };
  for (int depth = 0; depth < tr.max_depth; ++depth) {
    CountVertex();
    SurfaceHit hit;
    bool found = scene.Intersect(ray, &hit);
    Interval iv = m.Clip(ray, found ? hit.t : kInfinity);
    if (!iv.Empty()) {
      out->push_back({ray(iv.a), ray.d, iv.Length(), beta});
      if (tr.first_segment_only) return;
      // Continue the path: a free-flight distance; past the segment it reaches the surface
      // with weight 1 (probability and transmittance cancel).
      float d = iv.a - std::log(1 - rng.Uniform()) / m.SigmaT();
      if (d < iv.b) {
        beta *= m.Albedo();
        float u1 = rng.Uniform(), u2 = rng.Uniform();
        ray = {ray(d), SamplePhase(m.g, ray.d, u1, u2)};
        scattered = true;
        if (!survives(depth)) return;
        continue;
      }
    }
    if (!found) return;
    const Material& mat = scene.materials[static_cast<std::size_t>(hit.material)];
    if (mat.IsSpecular()) {
      if (!tr.light_caustics && !scattered) return;
      if (depth == 0) vpls = nullptr;
      BounceSpecular(mat, hit.p, hit.n, rng.Uniform(), &ray, &beta);
    } else {
      Vec3f nf = Dot(hit.n, ray.d) < 0 ? hit.n : -hit.n;
      if (vpls) vpls->push_back({hit.p, nf, beta * mat.albedo});
      beta *= mat.albedo;
      float u1 = rng.Uniform(), u2 = rng.Uniform();
      ray = {hit.p, SampleCosineHemisphere(nf, u1, u2)};
      scattered = true;
    }
    if (!survives(depth)) return;
  }
}

}  // namespace

Rotation LatticeRotation(const PointLight& light, std::uint64_t seed, std::uint64_t pass, std::size_t light_index) {
  if (!light.rotate_lattice) return {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  Rng rng(seed, pass, light_index, StreamPurpose::LatticeRotation);
  float u1 = rng.Uniform(), u2 = rng.Uniform(), u3 = rng.Uniform();
  return UniformRotation(u1, u2, u3);
}

std::vector<Vrl> TraceLightPaths(const Scene& scene, const TransportSettings& transport, int count,
                                 std::uint64_t seed, std::uint64_t pass, std::vector<Vpl>* vpls, double* work) {
  LatticeRotations rotations;
  for (std::size_t k = 0; k < scene.lights.points.size(); ++k)
    rotations.push_back(LatticeRotation(scene.lights.points[k], seed, pass, k));
  std::vector<std::vector<Vrl>> per_path(static_cast<std::size_t>(count));
  std::vector<std::vector<Vpl>> vpls_per_path(vpls ? static_cast<std::size_t>(count) : 0);
  std::vector<double> path_work(static_cast<std::size_t>(count));  // summed in order: not by thread
  tbb::parallel_for(0, count, [&](int i) {
    Rng rng(seed, pass, static_cast<std::uint64_t>(i), StreamPurpose::LightPath);
    const auto k = static_cast<std::size_t>(i);
    WorkScope scope(&path_work[k], false);
    TracePath(scene, transport, rotations, i, count, rng, &per_path[k], vpls ? &vpls_per_path[k] : nullptr);
  });
  if (work)
    for (double w : path_work) *work += w;
  std::vector<Vrl> vrls;
  for (const auto& p : per_path) vrls.insert(vrls.end(), p.begin(), p.end());
  if (vpls) {
    vpls->clear();
    for (const auto& p : vpls_per_path) vpls->insert(vpls->end(), p.begin(), p.end());
  }
  return vrls;
}

}  // namespace vrlis::integration
