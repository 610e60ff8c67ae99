// The example renderer's own counted work (vrlis_integration/renderer_work.hpp, written by
// tools/work_costs.sh), per scene:
//   Work/ray/<intersect|occluded>/<scene>  one ray of the scene's Embree geometry: closest hits
//       along camera rays through the image; occlusion between points on two of them (the
//       camera gathers' connections join such points)
//   Work/renderer/call/<scene>   GatherMediumToMedium over a pass's VRLs along camera segments,
//       the control off (one sample per VRL), per VRL; the counter `counted` is the work its
//       record counts less kConnect (the library's operations, each visit's occlusion ray): the
//       rest is the integration's own per sample it connects
//   Work/renderer/remainder/<scene>  a 32 x 32 pass path-traced alone (VRL bound 0: no light
//       paths), the control off, per pixel; counters `counted` (its rays) and `vertices` (path
//       vertices per pixel): the rest is fitted over the scenes as kPixel + kVertex per vertex
//       (camera ray, film; shading, phase and light sampling, transmittance)
#include "bench_common.hpp"

#include <tbb/global_control.h>

#include <vrlis_integration/gather.hpp>
#include <vrlis_integration/light_paths.hpp>
#include <vrlis_integration/renderer.hpp>
#include <vrlis_integration/work.hpp>
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

constexpr const char* kScenes[] = {"room", "cube", "corner", "cloud", "fog", "bidirectional"};

void Call(benchmark::State& state, const char* name) {
  using namespace vrlis::integration;
  const RayPool pool = MakeRayPool(name);
  if (!pool.built) return state.SkipWithError("scene not built");
  const Scene& scene = pool.built->scene;
  const std::vector<Vrl> vrls = TraceLightPaths(scene, pool.built->transport, 32, 1, 0);
  std::vector<CameraSegment> segments;
  for (const Ray& ray : pool.rays) {
    SurfaceHit hit;
    const bool found = scene.geometry->Intersect(ray, kInfinity, &hit);
    const CameraSegment seg{ray, scene.medium.Clip(ray, found ? hit.t : kInfinity)};
    if (!seg.iv.Empty()) segments.push_back(seg);
  }
  if (segments.empty() || vrls.empty()) return state.SkipWithError("no camera segment in the medium, or no VRL");
  vrlis::integration::Rng rng(1, 0, 0, StreamPurpose::Camera);
  vrlis::PixelRecord record;  // the calls count their work here, their visits at kVisitWork
  GatherOptions options;
  options.effort.medium = pool.built->transport.effort;  // off in every scene's transport
  options.effort.visit_work = kVisitWork;
  options.effort.record = &record;
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        GatherMediumToMedium(pool.built->transport.sampling, scene, segments[i], vrls, rng, Spectrum(1.f), options));
    i = i + 1 == segments.size() ? 0 : i + 1;
  }
  const double items = double(state.iterations()) * double(vrls.size());
  state.SetItemsProcessed(static_cast<int64_t>(items));
  // The work counted without the constant this measures.
  state.counters["counted"] = record.medium.work / items - renderer_work::kConnect;
}

// A pixel path-traced alone (no light paths: the VRL bound 0), the control off.
void Remainder(benchmark::State& state, const char* name) {
  using namespace vrlis::integration;
  auto built = vrlis::scenes::BuildScene(name, {});
  if (!built) return state.SkipWithError("scene not built");
  RenderSettings settings;
  settings.width = settings.height = 32;
  settings.transport = built->transport;
  settings.transport.effort.on = false;
  settings.transport.vrl_bound = 0;
  VrlRenderer renderer(built->scene, settings);
  // One thread: the benchmark's rate is of its own thread's time.
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  double counted = 0, vertices = 0;
  std::uint64_t pass = 0;
  for (auto _ : state) {
    PassStats stats;
    benchmark::DoNotOptimize(renderer.RenderPass(1, pass++, &stats));
    counted += stats.work, vertices += double(stats.vertices);
  }
  const double pixels = double(state.iterations()) * settings.width * settings.height;
  state.SetItemsProcessed(static_cast<int64_t>(pixels));
  // The work counted without the constants this measures.
  state.counters["counted"] = (counted - renderer_work::kVertex * vertices) / pixels - renderer_work::kPixel;
  state.counters["vertices"] = vertices / pixels;
}

}  // namespace

void RegisterRendererWork() {
  for (const char* scene : kScenes) {
    for (bool occluded : {false, true})
      benchmark::RegisterBenchmark(
          (std::string("Work/ray/") + (occluded ? "occluded/" : "intersect/") + scene).c_str(),
          [scene, occluded](benchmark::State& s) { Rays(s, scene, occluded); });
    benchmark::RegisterBenchmark((std::string("Work/renderer/call/") + scene).c_str(),
                                 [scene](benchmark::State& s) { Call(s, scene); });
    benchmark::RegisterBenchmark((std::string("Work/renderer/remainder/") + scene).c_str(),
                                 [scene](benchmark::State& s) { Remainder(s, scene); });
  }
}

}  // namespace vrlis::bench
