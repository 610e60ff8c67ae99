// VrlPoint and VrlMarginal/step/g:<g>: step one alone (fit, sample_pdf).
#include <cmath>
#include <vector>

#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

// Step one alone, from the gather query: fit, sample, pdf.
template <typename StepOne>
void StepOneAlone(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  FitSamplePdf<StepOne>(state, [&](size_t i) -> const MediumGatherQuery<float>& { return pools.configs[i].query; },
                        [&](size_t i) { return pools.configs[i].xi_vrl; });
}

// VrlPoint from the camera line alone (no gather query to validate): what older commits'
// VrlPoint benchmark timed, for tools/speed.sh's comparisons.
void VrlPointFromLine(benchmark::State& state) {
  const Pools& pools = PoolsFor(0.0);
  FitSamplePdf<VrlPoint<float>>(
      state, [&](size_t i) { return VrlPoint<float>::LineQuery(pools.configs[i].query.camera, pools.configs[i].query.vrl); },
      [&](size_t i) { return pools.configs[i].xi_vrl; });
}

// VrlMarginalBounded: the same over the pool's bounded camera segments only (each
// iteration takes the next one), for comparison with builds that reject unbounded ones
// (tools/speed.sh against older commits).
void VrlMarginalBounded(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  std::vector<size_t> bounded;  // kPool indices, cycling through the bounded configurations
  for (size_t i = 0; bounded.size() < kPool; i = (i + 1) & (kPool - 1))
    if (std::isfinite(pools.configs[i].query.camera.tmax)) bounded.push_back(i);
  FitSamplePdf<VrlMarginal<float>>(
      state, [&](size_t i) -> const MediumGatherQuery<float>& { return pools.configs[bounded[i]].query; },
      [&](size_t i) { return pools.configs[bounded[i]].xi_vrl; });
}

}  // namespace

void RegisterVrlPoint() {
  benchmark::RegisterBenchmark("VrlPoint", [](benchmark::State& s) { StepOneAlone<VrlPoint<float>>(s, 0.0); });
  benchmark::RegisterBenchmark("VrlPointFromLine", VrlPointFromLine);
  for (double g : kStudyG)
    benchmark::RegisterBenchmark(BenchName("VrlMarginal", "step", g).c_str(),
                                 [g](benchmark::State& s) { StepOneAlone<VrlMarginal<float>>(s, g); });
  for (double g : kStudyG)
    benchmark::RegisterBenchmark(BenchName("VrlMarginalBounded", "step", g).c_str(),
                                 [g](benchmark::State& s) { VrlMarginalBounded(s, g); });
}

}  // namespace vrlis::bench
