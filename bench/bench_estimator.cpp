// Estimator/<method>/g:<g>: the library's whole medium-to-medium gather without visibility
// (SampleMediumGather: step one by VrlPoint, the camera sampler, the integrand, f / pdf), as
// a renderer calls it. EstimatorMarginal/<method>/g:<g>: the same with VrlMarginal as step one.
#include <utility>

#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

void Estimator(benchmark::State& state, GatherSamplers method, double g) {
  const Pools& pools = PoolsFor(g);
  OverPool(state, [&](size_t i) {
    const Config<float>& c = pools.configs[i];
    GatherSample<float> s = SampleMediumGather(method, c.query, c.xi_vrl, c.xi_cam);
    benchmark::DoNotOptimize(s.weight);
  });
}

}  // namespace

void RegisterEstimator() {
  for (auto [kind, step_one] : {std::pair{"Estimator", VrlSamplers::Of<VrlPointEntry>()},
                                std::pair{"EstimatorMarginal", VrlSamplers::Of<VrlMarginalEntry>()}})
    for (SegmentChoice m : kSegmentSamplers)
      for (double g : kStudyG)
        benchmark::RegisterBenchmark(BenchName(kind, Name(m), g).c_str(),
                                     [m, step_one = step_one, g](benchmark::State& s) { Estimator(s, {m, step_one}, g); });
}

}  // namespace vrlis::bench
