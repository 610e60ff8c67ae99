// Work/ray/<intersect|occluded>/<scene>: one ray of the example scenes' Embree geometry, what
// the renderer counts its rays as (vrlis_integration/ray_work.hpp, by tools/work_costs.sh).
// Closest hits along camera rays through the image; occlusion between points on two of them
// (the camera gathers' connections join such points).
#include "bench_common.hpp"

#include <vrlis_scenes/scenes.hpp>

#include <algorithm>
#include <memory>
#include <vector>

namespace vrlis::bench {
namespace {

using vrlis::integration::Ray;
using vrlis::integration::Vec3f;

struct RayPool {
  std::shared_ptr<const vrlis::scenes::BuiltScene> built;
  std::vector<Ray> rays;
  std::vector<Vec3f> points;  // on the camera rays, before their first hit
};

RayPool MakeRayPool(const char* name) {
  RayPool pool;
  auto built = vrlis::scenes::BuildScene(name, {});
  if (!built) return pool;
  pool.built = std::make_shared<const vrlis::scenes::BuiltScene>(std::move(*built));
  const vrlis::integration::Scene& scene = pool.built->scene;
  double u = 0.5, v = 0.5;
  for (size_t i = 0; i < kPool; ++i) {
    u = u + 0.6180339887 - (u + 0.6180339887 >= 1 ? 1 : 0), v = v + 0.7548776662 - (v + 0.7548776662 >= 1 ? 1 : 0);
    const Ray ray = scene.camera.Generate(float(64 * u), float(64 * v), 64, 64);
    vrlis::integration::SurfaceHit hit;
    const bool found = scene.geometry->Intersect(ray, vrlis::integration::kInfinity, &hit);
    pool.rays.push_back(ray);
    pool.points.push_back(ray(float((found ? std::min(hit.t, 20.f) : 20.f) * (0.1 + 0.8 * v))));
  }
  return pool;
}

void Rays(benchmark::State& state, const char* name, bool occluded) {
  const RayPool pool = MakeRayPool(name);
  if (!pool.built) return state.SkipWithError("scene not built");
  const vrlis::integration::Geometry& geometry = *pool.built->scene.geometry;
  size_t i = 0;
  for (auto _ : state) {
    if (occluded) {
      benchmark::DoNotOptimize(geometry.Occluded(pool.points[i], pool.points[(i * 7 + 3) & (kPool - 1)]));
    } else {
      vrlis::integration::SurfaceHit hit;
      benchmark::DoNotOptimize(geometry.Intersect(pool.rays[i], vrlis::integration::kInfinity, &hit));
    }
    i = (i + 1) & (kPool - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

void RegisterRays() {
  for (const char* scene : {"room", "cube", "corner", "cloud", "fog", "bidirectional"})
    for (bool occluded : {false, true})
      benchmark::RegisterBenchmark(
          (std::string("Work/ray/") + (occluded ? "occluded/" : "intersect/") + scene).c_str(),
          [scene, occluded](benchmark::State& s) { Rays(s, scene, occluded); });
}

}  // namespace vrlis::bench
