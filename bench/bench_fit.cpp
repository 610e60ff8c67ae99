// Fit/<method>/g:<g>: the fit alone.
#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

template <typename Sampler>
void Fit(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  size_t i = 0;
  for (auto _ : state) {
    Sampler s(pools.camera[i]);
    benchmark::DoNotOptimize(s);
    i = (i + 1) & (kPool - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

void RegisterFit() {
  RegisterPerSampler("Fit", [](auto tag, benchmark::State& s, double g) { Fit<typename decltype(tag)::type>(s, g); });
}

}  // namespace vrlis::bench
