#pragma once
// Shared by the vrlis_bench translation units: the pools of random queries and the naming.
//
// Each kind of benchmark (Camera, Fit, Estimator, VrlPoint) lives in its own translation
// unit, so that each sampler is constructed from one call site per unit, as in a renderer:
// with several call sites in one unit the compiler stops inlining the fits, which would
// time the harness rather than the samplers (measured: +50 ns on CauchySum and Novak).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "study/integrand.hpp"

namespace vrlis::bench {

using namespace vrlis::study;
inline constexpr size_t kPool = 1024;  // a power of two: the index wraps with a mask

struct Pools {
  std::vector<Pair<float>> pairs;
  std::vector<SegmentQuery<float>> camera;  // each pair's camera query at its fixed VRL point
  std::vector<VrlPointQuery<float>> vrl;
};

// The pool of kPool seeded random pairs for one g (built on first use, outside timing).
const Pools& PoolsFor(double g);

inline std::string BenchName(const char* kind, const char* sampler, double g) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s/%s/g:%.2f", kind, sampler, g);
  return buf;
}

// Registers kind/<Sampler>/g:<g> for every camera sampler and every g of the study;
// run(tag, state, g) times sampler type decltype(tag)::type.
template <typename Run, typename... S>
void RegisterPerSampler(const char* kind, Run run, std::tuple<S...>*) {
  int k = 0;
  ((void)[&] {
     const char* name = kCameraSamplerNames[k++];
     for (double g : kStudyG)
       benchmark::RegisterBenchmark(BenchName(kind, name, g).c_str(),
                                    [run, g](benchmark::State& state) { run(std::common_type<S>{}, state, g); });
   }(), ...);
}
template <typename Run>
void RegisterPerSampler(const char* kind, Run run) {
  RegisterPerSampler(kind, run, static_cast<SamplerTuple<float>*>(nullptr));
}

void RegisterCamera();
void RegisterFit();
void RegisterEstimator();
void RegisterVrlPoint();
void RegisterGather();

}  // namespace vrlis::bench
