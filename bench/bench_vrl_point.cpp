// VrlPoint and VrlMarginal/g:<g>: step one alone (fit, sample, pdf).
#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

// Step one alone, from the gather query: fit, sample, pdf.
template <typename StepOne>
void StepOneAlone(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  OverPool(state, [&](size_t i) {
    StepOne s(pools.configs[i].query);
    float v = s.sample(pools.configs[i].xi_vrl);
    float pdf = s.pdf(v);
    benchmark::DoNotOptimize(v);
    benchmark::DoNotOptimize(pdf);
  });
}

}  // namespace

void RegisterVrlPoint() {
  benchmark::RegisterBenchmark("VrlPoint", [](benchmark::State& s) { StepOneAlone<VrlPoint<float>>(s, 0.0); });
  for (double g : kStudyG)
    benchmark::RegisterBenchmark(BenchName("VrlMarginal", "step", g).c_str(),
                                 [g](benchmark::State& s) { StepOneAlone<VrlMarginal<float>>(s, g); });
}

}  // namespace vrlis::bench
