// VrlPoint: step one alone (fit, sample, pdf).
#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

void VrlPointStep(benchmark::State& state) {
  const Pools& pools = PoolsFor(0.0);
  size_t i = 0;
  for (auto _ : state) {
    VrlPoint<float> vp(pools.vrl[i]);
    float v = vp.sample(pools.pairs[i].xi_vrl);
    float pdf = vp.pdf(v);
    benchmark::DoNotOptimize(v);
    benchmark::DoNotOptimize(pdf);
    i = (i + 1) & (kPool - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

void RegisterVrlPoint() { benchmark::RegisterBenchmark("VrlPoint", VrlPointStep); }

}  // namespace vrlis::bench
