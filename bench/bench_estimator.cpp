// Estimator/<Sampler>/g:<g>: the whole medium-to-medium step without visibility, step one by
// VrlPoint. EstimatorMarginal/<Sampler>/g:<g>: the same with VrlMarginal as step one.
#include <type_traits>

#include "bench_common.hpp"

namespace vrlis::bench {
namespace {

template <typename Sampler, typename StepOne>
void Estimator(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  size_t i = 0;
  for (auto _ : state) {
    const Pair<float>& p = pools.pairs[i];
    StepOne vp([&] {
      if constexpr (std::is_same_v<StepOne, VrlPoint<float>>) return VrlQuery(p);
      else return MarginalQuery(p);
    }());
    float v = vp.sample(p.xi_vrl);
    float p1 = vp.pdf(v);
    Vec3<float> y = VrlPointAt(p, v);
    Sampler s(CameraQuery(p, y));
    float u = s.sample(p.xi_cam);
    float p2 = s.pdf(u);
    float f = IntegrandAt(p, u, y, v);
    float estimate = p1 * p2 > 0 ? f / (p1 * p2) : 0.0f;
    benchmark::DoNotOptimize(estimate);
    i = (i + 1) & (kPool - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

void RegisterEstimator() {
  RegisterPerSampler("Estimator", [](auto tag, benchmark::State& s, double g) {
    Estimator<typename decltype(tag)::type, VrlPoint<float>>(s, g);
  });
  RegisterPerSampler("EstimatorMarginal", [](auto tag, benchmark::State& s, double g) {
    Estimator<typename decltype(tag)::type, VrlMarginal<float>>(s, g);
  });
}

}  // namespace vrlis::bench
