// Camera/<method>/g:<g>: fit from a query, sample, pdf.
#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

template <typename Sampler>
void Camera(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  OverPool(state, [&](size_t i) {
    Sampler s(pools.camera[i]);
    float t = s.sample(pools.configs[i].xi_cam);
    float pdf = s.pdf(t);
    benchmark::DoNotOptimize(t);
    benchmark::DoNotOptimize(pdf);
  });
}

}  // namespace

void RegisterCamera() {
  RegisterPerSampler("Camera", [](auto tag, benchmark::State& s, double g) { Camera<typename decltype(tag)::type>(s, g); });
}

}  // namespace vrlis::bench
