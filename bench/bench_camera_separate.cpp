// CameraSeparate/<method>/g:<g>: fit from a query, sample(u), then pdf(t): the two calls
// sample_pdf fuses. Against Camera/ (same pool, same u) it is what the fused call saves.
#include "bench_common.hpp"

namespace vrlis::bench {

void RegisterCameraSeparate() {
  RegisterOverPools("CameraSeparate", [](auto tag, const Pools& pools, size_t i) {
    typename decltype(tag)::type s(pools.camera[i]);
    float t = s.sample(pools.configs[i].xi_cam);
    SegmentSample<float> sample{t, s.pdf(t)};
    benchmark::DoNotOptimize(sample);
  });
}

}  // namespace vrlis::bench
