// Fit/<method>/g:<g>: the fit alone.
#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

template <typename Sampler>
void Fit(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  OverPool(state, [&](size_t i) {
    Sampler s(pools.camera[i]);
    benchmark::DoNotOptimize(s);
  });
}

}  // namespace

void RegisterFit() {
  RegisterPerSampler("Fit", [](auto tag, benchmark::State& s, double g) { Fit<typename decltype(tag)::type>(s, g); });
}

}  // namespace vrlis::bench
