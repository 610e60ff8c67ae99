// VrlPoint and VrlMarginal/g:<g>: step one alone (fit, sample, pdf).
#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

void VrlPointStep(benchmark::State& state) {
  const Pools& pools = PoolsFor(0.0);
  size_t i = 0;
  for (auto _ : state) {
    VrlPoint<float> vp(pools.configs[i].query);
    float v = vp.sample(pools.configs[i].xi_vrl);
    float pdf = vp.pdf(v);
    benchmark::DoNotOptimize(v);
    benchmark::DoNotOptimize(pdf);
    i = (i + 1) & (kPool - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

void VrlMarginalStep(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  size_t i = 0;
  for (auto _ : state) {
    VrlMarginal<float> vm(pools.configs[i].query);
    float v = vm.sample(pools.configs[i].xi_vrl);
    float pdf = vm.pdf(v);
    benchmark::DoNotOptimize(v);
    benchmark::DoNotOptimize(pdf);
    i = (i + 1) & (kPool - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

void RegisterVrlPoint() {
  benchmark::RegisterBenchmark("VrlPoint", VrlPointStep);
  for (double g : kStudyG)
    benchmark::RegisterBenchmark(BenchName("VrlMarginal", "step", g).c_str(),
                                 [g](benchmark::State& s) { VrlMarginalStep(s, g); });
}

}  // namespace vrlis::bench
