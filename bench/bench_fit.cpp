// Fit/<method>/g:<g>: the fit alone.
#include "bench_common.hpp"

namespace vrlis::bench {

void RegisterFit() {
  RegisterOverPools("Fit", [](auto tag, const Pools& pools, size_t i) {
    typename decltype(tag)::type s(pools.camera[i]);
    benchmark::DoNotOptimize(s);
  });
}

}  // namespace vrlis::bench
