// The operations the effort control counts as work (vrlis/effort/work.hpp), where the batched
// gathers' own benchmarks (GatherBatch/, SurfaceGatherBatch/) do not already time them; one
// item is one VRL. tools/work_costs.sh turns these and those into the work constants.
//
//   Work/bound/<medium|surface>-<quick|tight>  the bounds of 8 VRLs at once, in lanes
//   Work/call/<method>     GatherMediumVrls over 256 VRLs, the control off, a visitor that
//                          only sums: the call's loop per VRL beyond its batched samples
//   Work/call-decided/<method>  the same with every gather decided, unpriced (each still
//                          taken once): beyond Work/call/ and both bounds, a decision's own
//   Work/mixture-density   GatherBatch of `auto` with its samples' density over the mixture
//                          (measure_mixture), over the same without it, per sample
#include "bench_common.hpp"

#include <vrlis/gather/gather_instances.hpp>
#include <vrlis/gather/gather_vrls.hpp>

#include <vector>

// Every sampler pair's batches, compiled once in vrlis::integration (its CMakeLists.txt).
VRLIS_EXTERN_GATHERS(float)

namespace vrlis::bench {
namespace {

constexpr double kWorkG = 0.5;

std::vector<VrlSegment<float>> PoolVrls(const Pools& pools) {
  std::vector<VrlSegment<float>> vrls;
  for (const Config<float>& c : pools.configs) vrls.push_back(c.query.vrl);
  return vrls;
}

void Bound(benchmark::State& state, bool surface, bool tight) {
  const Pools& pools = PoolsFor(kWorkG);
  const std::vector<VrlSegment<float>> vrls = PoolVrls(pools);
  float quick_out[kBoundBatch], tight_out[kBoundBatch];
  size_t b = 0;
  const size_t blocks = vrls.size() / kBoundBatch;
  for (auto _ : state) {
    const MediumGatherQuery<float>& q = pools.configs[b * kBoundBatch].query;
    float* quick = tight ? nullptr : quick_out;
    float* tight_bound = tight ? tight_out : nullptr;
    if (surface)
      SurfaceGatherBounds(q.camera.origin, q.camera.dir, &vrls[b * kBoundBatch], kBoundBatch, q.medium, quick,
                          tight_bound);
    else
      MediumGatherBounds(q.camera, &vrls[b * kBoundBatch], kBoundBatch, q.medium, quick, tight_bound);
    benchmark::DoNotOptimize(quick_out);
    benchmark::DoNotOptimize(tight_out);
    b = b + 1 == blocks ? 0 : b + 1;
  }
  state.SetItemsProcessed(state.iterations() * kBoundBatch);
}

void Call(benchmark::State& state, SegmentChoice method, bool decided) {
  constexpr int kVrls = 256;
  const Pools& pools = PoolsFor(kWorkG);
  const std::vector<VrlSegment<float>> vrls = PoolVrls(pools);
  EffortSettings effort;
  effort.on = effort.decide = decided;
  const std::vector<float> weights(kVrls, 1.f);
  // VrlPoint as step one, fixed at compile time: the pairs with VrlMarginal are not built.
  SegmentSamplers::WithEntry(method, [&](auto entry) {
    const FixedSamplers<decltype(entry)> samplers;
    size_t first = 0;
    float u = 0.5f;
    for (auto _ : state) {
      const MediumGatherQuery<float>& q = pools.configs[first].query;
      float sum = 0;
      GatherMediumVrls(samplers, q.camera, q.medium, &vrls[first], kVrls,
                       [&] { return u = u + 0.618034f >= 1 ? u - 0.381966f : u + 0.618034f; },
                       [&](int, const GatherSample<float>& s, float w) { sum += w * s.weight; },
                       EffortCall<float>{effort, weights.data()});
      benchmark::DoNotOptimize(sum);
      first = first + 2 * kVrls > vrls.size() ? 0 : first + kVrls;
    }
  });
  state.SetItemsProcessed(state.iterations() * kVrls);
}

void MixtureDensity(benchmark::State& state, bool measured) {
  const Pools& pools = PoolsFor(kWorkG);
  const std::vector<VrlSegment<float>> vrls = PoolVrls(pools);
  std::vector<float> u_vrl, u_camera;
  for (const Config<float>& c : pools.configs) u_vrl.push_back(c.xi_vrl), u_camera.push_back(c.xi_cam);
  GatherSample<float> out[kGatherChunk];
  size_t b = 0;
  const size_t batches = vrls.size() / kGatherChunk;
  for (auto _ : state) {
    const size_t first = b * kGatherChunk;
    const MediumGatherQuery<float>& q = pools.configs[first].query;
    SampleMediumGathers<VrlPointEntry::Sampler<float>, AutoEntry::Sampler<float>>(
        ValidQuery{}, q.camera, q.medium, &vrls[first], kGatherChunk, &u_vrl[first], &u_camera[first], out, measured);
    benchmark::DoNotOptimize(out);
    b = b + 1 == batches ? 0 : b + 1;
  }
  state.SetItemsProcessed(state.iterations() * kGatherChunk);
}

}  // namespace

void RegisterWork() {
  for (bool surface : {false, true})
    for (bool tight : {false, true}) {
      const std::string name =
          std::string("Work/bound/") + (surface ? "surface" : "medium") + (tight ? "-tight" : "-quick");
      benchmark::RegisterBenchmark(name.c_str(), [surface, tight](benchmark::State& s) { Bound(s, surface, tight); });
    }
  for (bool decided : {false, true})
    for (SegmentChoice method : kSegmentSamplers)
      benchmark::RegisterBenchmark(
          ((decided ? "Work/call-decided/" : "Work/call/") + std::string(method.name())).c_str(),
          [method, decided](benchmark::State& s) { Call(s, method, decided); });
  benchmark::RegisterBenchmark("Work/mixture-density/measured", [](benchmark::State& s) { MixtureDensity(s, true); });
  benchmark::RegisterBenchmark("Work/mixture-density/plain", [](benchmark::State& s) { MixtureDensity(s, false); });
}

}  // namespace vrlis::bench
