// The library's medium-to-medium gather as a renderer calls it, and its parts:
//
//   Gather/<method>/g:<g>   SampleMediumGather: validation, step one (VrlPoint: fit, sample,
//                           pdf), the camera sampler chosen at run time (fit, sample, pdf),
//                           the integrand and the weight; everything but the occlusion ray
//   GatherBatch/<method>/g:<g>  SampleMediumGathers: one camera segment against kGatherChunk
//                           VRLs (the camera of configuration 32k, the VRLs of 32k .. 32k + 31,
//                           the renderer's batches), time per iteration, that is per batch
//                           (divide by 32 for one gather); every camera sampler with every
//                           step one (`novak`, `novak+marginal`, ...: the renderer's names)
//   GatherBatchDouble/<method>/g:<g>  the same in double (the same configurations, converted):
//                           the price of double precision (docs/porting.md#precision)
//   SurfaceGatherBatch/<method>/g:<g>  SampleSurfaceGathers: the VRLs of 8k .. 8k + 7 seen from
//                           the camera origin of configuration 8k, a surface point whose normal is
//                           that camera's direction (the medium-to-surface gather); per batch
//   GatherPart/validate     Validate(MediumGatherQuery)
//   GatherPart/step-one     VrlPoint from the gather query, sample_pdf
//   GatherPart/integrand    MediumGatherIntegrand at a sampled (t, v), with its transmittance
//
// The camera step's own parts are Fit/<Sampler> (the fit) and Camera/<Sampler> (fit, sample,
// pdf). docs/bench.md (section "Cost of one gather") puts these together with a profile of
// vrl_render (occlusion ray, random numbers, bookkeeping).
#include "bench_common.hpp"

#include <vrlis/gather/gather_instances.hpp>
#include <vrlis/gather/medium_gather.hpp>
#include <vrlis/gather/surface_gather.hpp>

#include <vector>

// Every sampler pair's batches, compiled once: in float in vrlis::integration, in double
// for GatherBatchDouble (CMakeLists.txt).
VRLIS_EXTERN_GATHERS(float)
VRLIS_EXTERN_GATHERS(double)

namespace vrlis::bench {
namespace {

inline constexpr double kGatherG[] = {-0.9, 0.5, 0.9};

const MediumGatherQuery<float>& GatherQuery(const Config<float>& c) { return c.query; }

void Gather(benchmark::State& state, SegmentChoice method, double g) {
  const Pools& pools = PoolsFor(g);
  GatherSamplers m{method, VrlSamplers::Of<VrlPointEntry>()};
  OverPool(state, [&](size_t i) {
    GatherSample<float> s = SampleMediumGather(m, pools.configs[i].query, pools.configs[i].xi_vrl, pools.configs[i].xi_cam);
    benchmark::DoNotOptimize(s);
  });
}

// The pool's queries, VRLs and random numbers as the arrays the batched gathers take, in Real.
template <typename Real>
struct BatchInputs {
  std::vector<MediumGatherQuery<Real>> queries;
  std::vector<VrlSegment<Real>> vrls;
  std::vector<Real> u_vrl, u_camera;
};
template <typename Real>
BatchInputs<Real> BatchInputsOf(const Pools& pools) {
  BatchInputs<Real> in;
  for (const Config<float>& f : pools.configs) {
    const Config<Real> c = f.template as<Real>();
    in.queries.push_back(c.query);
    in.vrls.push_back(c.query.vrl);
    in.u_vrl.push_back(c.xi_vrl);
    in.u_camera.push_back(c.xi_cam);
  }
  return in;
}

template <typename Real>
void GatherBatch(benchmark::State& state, GatherSamplers method, double g) {
  const BatchInputs<Real> in = BatchInputsOf<Real>(PoolsFor(g));
  const size_t batches = in.vrls.size() / kGatherChunk;
  WithGatherSamplers<Real>(method, [&](auto step_one, auto step_two) {
    GatherSample<Real> out[kGatherChunk];
    size_t b = 0;
    for (auto _ : state) {
      const size_t first = b * kGatherChunk;
      const MediumGatherQuery<Real>& q = in.queries[first];
      SampleMediumGathers<typename decltype(step_one)::type, typename decltype(step_two)::type>(
          ValidQuery{}, q.camera, q.medium, &in.vrls[first], kGatherChunk, &in.u_vrl[first], &in.u_camera[first], out);
      benchmark::DoNotOptimize(out);
      b = b + 1 == batches ? 0 : b + 1;
    }
  });
  state.SetItemsProcessed(state.iterations() * kGatherChunk);
}

void SurfaceGatherBatch(benchmark::State& state, SegmentChoice method, double g) {
  const BatchInputs<float> in = BatchInputsOf<float>(PoolsFor(g));
  const size_t batches = in.vrls.size() / kVrlPointBatch;
  SegmentSamplers::WithEntry(method, [&](auto entry) {
    GatherSample<float> out[kVrlPointBatch];
    size_t b = 0;
    for (auto _ : state) {
      const size_t first = b * kVrlPointBatch;
      const MediumGatherQuery<float>& q = in.queries[first];
      SampleSurfaceGathers<typename decltype(entry)::template Sampler<float>>(
          ValidQuery{}, q.camera.origin, q.camera.dir, q.medium, &in.vrls[first], kVrlPointBatch, &in.u_vrl[first], out);
      benchmark::DoNotOptimize(out);
      b = b + 1 == batches ? 0 : b + 1;
    }
  });
  state.SetItemsProcessed(state.iterations() * kVrlPointBatch);
}

void Validation(benchmark::State& state) {
  const Pools& pools = PoolsFor(0.5);
  OverPool(state, [&](size_t i) {
    QueryError e = Validate(GatherQuery(pools.configs[i]));
    benchmark::DoNotOptimize(e);
  });
}

void StepOne(benchmark::State& state) {
  const Pools& pools = PoolsFor(0.5);
  OverPool(state, [&](size_t i) {
    VrlPoint<float> vp(GatherQuery(pools.configs[i]));
    SegmentSample<float> v = vp.sample_pdf(pools.configs[i].xi_vrl);
    benchmark::DoNotOptimize(v);
  });
}

void Integrand(benchmark::State& state) {
  const Pools& pools = PoolsFor(0.5);
  OverPool(state, [&](size_t i) {
    const Config<float>& c = pools.configs[i];
    const auto& q = c.query;
    float transmittance = 0;
    float t = std::isfinite(q.camera.tmax) ? q.camera.tmin + c.xi_cam * (q.camera.tmax - q.camera.tmin) : q.camera.tmin + c.xi_cam;
    float f = MediumGatherIntegrand(q, t, c.xi_vrl * q.vrl.length, &transmittance);
    benchmark::DoNotOptimize(f);
    benchmark::DoNotOptimize(transmittance);
  });
}

}  // namespace

void RegisterGather() {
  for (SegmentChoice method : kSegmentSamplers)
    for (double g : kGatherG)
      benchmark::RegisterBenchmark(BenchName("Gather", std::string(method.name()).c_str(), g).c_str(),
                                   [method, g](benchmark::State& s) { Gather(s, method, g); });
  for (SegmentChoice method : kSegmentSamplers)
    for (double g : kGatherG)
      for (VrlChoice one : kVrlSamplers) {
        const GatherSamplers both{method, one};
        benchmark::RegisterBenchmark(BenchName("GatherBatch", Name(both), g).c_str(),
                                     [both, g](benchmark::State& s) { GatherBatch<float>(s, both, g); });
      }
  for (SegmentChoice method : kSegmentSamplers)
    for (double g : kGatherG)
      benchmark::RegisterBenchmark(
          BenchName("GatherBatchDouble", std::string(method.name()).c_str(), g).c_str(),
          [method, g](benchmark::State& s) { GatherBatch<double>(s, {method, VrlSamplers::Of<VrlPointEntry>()}, g); });
  for (SegmentChoice method : kSegmentSamplers)
    for (double g : kGatherG)
      benchmark::RegisterBenchmark(BenchName("SurfaceGatherBatch", std::string(method.name()).c_str(), g).c_str(),
                                   [method, g](benchmark::State& s) { SurfaceGatherBatch(s, method, g); });
  benchmark::RegisterBenchmark("GatherPart/validate", Validation);
  benchmark::RegisterBenchmark("GatherPart/step-one", StepOne);
  benchmark::RegisterBenchmark("GatherPart/integrand", Integrand);
}

}  // namespace vrlis::bench
