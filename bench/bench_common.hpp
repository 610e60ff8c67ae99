#pragma once
// Shared by the vrlis_bench translation units: the pools of random queries and the naming.
//
// Each kind of benchmark (Camera, Fit, Estimator, VrlPoint) lives in its own translation
// unit, so that each sampler is constructed from one call site per unit, as in a renderer:
// with several call sites in one unit the compiler stops inlining the fits, which would
// time the harness rather than the samplers (measured: +50 ns on CauchySum and Novak).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "study/config.hpp"

namespace vrlis::bench {

using namespace vrlis::study;
inline constexpr size_t kPool = 1024;  // a power of two: the index wraps with a mask

struct Pools {
  std::vector<Config<float>> configs;
  std::vector<SegmentQuery<float>> camera;  // each configuration's camera query at its fixed VRL point
};

// The pool of kPool seeded random configurations for one g (built on first use, outside timing).
const Pools& PoolsFor(double g);

// The timed loop every benchmark shares: body(i) once per iteration, i cycling through the
// pool in order.
template <typename Body>
void OverPool(benchmark::State& state, Body body) {
  size_t i = 0;
  for (auto _ : state) {
    body(i);
    i = (i + 1) & (kPool - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

// The timed body of Camera/ and of step one alone: fit a Sampler from query(i), then a
// sample at xi(i) with its density (sample_pdf, one call).
template <typename Sampler, typename Query, typename Xi>
void FitSamplePdf(benchmark::State& state, Query query, Xi xi) {
  OverPool(state, [&](size_t i) {
    Sampler s(query(i));
    SegmentSample<float> sample = s.sample_pdf(xi(i));  // the fused call renderers make
    benchmark::DoNotOptimize(sample);
  });
}

inline std::string BenchName(const char* kind, std::string_view sampler, double g) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s/%.*s/g:%.2f", kind, int(sampler.size()), sampler.data(), g);
  return buf;
}

// Registers kind/<method>/g:<g> for every camera sampler of the library's registry
// (vrlis::SegmentSamplers, with its names) and every g of the study; run(tag, state, g)
// times the sampler type decltype(tag)::type, so that each sampler is built at its own call
// site (SegmentSamplers::With would put all five in one function, and the compiler then
// stops inlining the fits: measured 1.3-1.7x slower).
template <typename Run, typename... Entries>
void RegisterPerSampler(const char* kind, Run run, Registry<Entries...>*) {
  ((void)[&] {
     using Sampler = typename Entries::template Sampler<float>;
     for (double g : kStudyG)
       benchmark::RegisterBenchmark(BenchName(kind, Entries::kName, g).c_str(),
                                    [run, g](benchmark::State& state) { run(std::common_type<Sampler>{}, state, g); });
   }(), ...);
}
template <typename Run>
void RegisterPerSampler(const char* kind, Run run) {
  RegisterPerSampler(kind, run, static_cast<SegmentSamplers*>(nullptr));
}

// RegisterPerSampler with the timed loop over the pool of g: kind/<method>/g:<g> runs
// body(tag, pools, i), decltype(tag)::type the sampler, for i cycling through the pool.
template <typename Body>
void RegisterOverPools(const char* kind, Body body) {
  RegisterPerSampler(kind, [body](auto tag, benchmark::State& state, double g) {
    const Pools& pools = PoolsFor(g);
    OverPool(state, [&](size_t i) { body(tag, pools, i); });
  });
}

void RegisterCamera();
void RegisterCameraSeparate();
// SceneCamera/<method> over the queries of a log file; false (and *error) if it cannot be read.
bool RegisterSceneCamera(const std::string& path, std::string* error);
void RegisterFit();
void RegisterEstimator();
void RegisterVrlPoint();
void RegisterGather();
void RegisterWork();
// Work/ray/..., Work/renderer/...: only where the lab is built with the example scenes
// (VRLIS_BENCH_RENDERER).
void RegisterRendererWork();

}  // namespace vrlis::bench
