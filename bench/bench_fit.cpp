// Fit/<Sampler>/g:<g>: the fit alone.
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

template <typename... S>
void RegisterAll(std::tuple<S...>*) {
  int k = 0;
  ((void)[&] {
     const char* name = kCameraSamplerNames[k++];
     for (double g : kStudyG)
       benchmark::RegisterBenchmark(BenchName("Fit", name, g).c_str(), [g](benchmark::State& s) { Fit<S>(s, g); });
   }(), ...);
}

}  // namespace

void RegisterFit() { RegisterAll(static_cast<CameraSamplers<float>*>(nullptr)); }

}  // namespace vrlis::bench
