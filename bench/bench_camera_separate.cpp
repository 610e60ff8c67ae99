// CameraSeparate/<method>/g:<g>: fit from a query, sample(u), then pdf(t): the two calls
// sample_pdf fuses. Against Camera/ (same pool, same u) it is what the fused call saves.
#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

template <typename Sampler>
void CameraSeparate(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  OverPool(state, [&](size_t i) {
    Sampler s(pools.camera[i]);
    float t = s.sample(pools.configs[i].xi_cam);
    SegmentSample<float> sample{t, s.pdf(t)};
    benchmark::DoNotOptimize(sample);
  });
}

}  // namespace

void RegisterCameraSeparate() {
  RegisterPerSampler("CameraSeparate",
                     [](auto tag, benchmark::State& s, double g) { CameraSeparate<typename decltype(tag)::type>(s, g); });
}

}  // namespace vrlis::bench
