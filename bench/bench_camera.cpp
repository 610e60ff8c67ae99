// Camera/<method>/g:<g>: fit from a query, sample, pdf.
#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

template <typename Sampler>
void Camera(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  FitSamplePdf<Sampler>(state, [&](size_t i) -> const SegmentQuery<float>& { return pools.camera[i]; },
                        [&](size_t i) { return pools.configs[i].xi_cam; });
}

}  // namespace

void RegisterCamera() {
  RegisterPerSampler("Camera", [](auto tag, benchmark::State& s, double g) { Camera<typename decltype(tag)::type>(s, g); });
}

}  // namespace vrlis::bench
