// vrlis_bench: the cost of one sample as a renderer pays it, with Google Benchmark.
//
//   Camera/<method>/g:<g>      build the sampler from a query (the fit), then sample_pdf
//   CameraSeparate/...         the same with sample, then pdf of the sample (unfused)
//   SceneCamera/<method>       Camera/ on a render's own queries: only with
//                              --vrlis_queries=FILE (a log of vrl_render --dump-queries)
//   Fit/<method>/g:<g>         the fit alone (where Camera's time goes)
//   Estimator/<method>/g:<g>   the library's whole medium-to-medium gather without visibility
//                              (SampleMediumGather): VrlPoint (fit, sample, pdf), the camera
//                              sampler (fit, sample, pdf), the integrand, f / (p1 p2)
//   EstimatorMarginal/...      the same with VrlMarginal as step one
//   VrlPoint                   step one alone (fit, sample, pdf); independent of g
//   VrlMarginal/step/g:<g>     VrlMarginal alone
//   VrlMarginalBounded/step/g:<g>  the same over the bounded camera segments only
//   Gather/<method>/g:<g>      the library's whole gather call, and GatherPart/*: its parts
//   Work/...                   the effort control's counted operations (bench_work.cpp,
//                              bench_renderer_work.cpp; tools/work_costs.sh)
//
// --vrlis_lanes=built runs the batched gathers as built rather than on the widest lanes the
// processor has (core/dispatch.hpp: vrlis::UseWidestLanes).
//
// Every benchmark cycles in order through a pool of 1024 random configurations (those of
// the accuracy study, seeded), so that no single warm branch is timed. Float throughout;
// samplers are chosen through the library's registry (SegmentSamplers::With: one predictable
// branch, the concrete type inside). One iteration is one sample.
// Standard flags apply: --benchmark_filter=Novak, --benchmark_format=json, ...
#include <map>
#include <memory>
#include <string>

#include <vrlis/core/dispatch.hpp>

#include "bench_common.hpp"

namespace vrlis::bench {

const Pools& PoolsFor(double g) {
  static std::map<double, std::unique_ptr<Pools>> cache;
  auto& slot = cache[g];
  if (!slot) {
    slot = std::make_unique<Pools>();
    for (const Config<double>& cd : MakeConfigs(kDefaultSeed, int(kPool), g)) {
      Config<float> c = cd.as<float>();
      VrlPoint<float> vp(c.query);
      slot->configs.push_back(c);
      slot->camera.push_back(CameraStepQuery(c.query, c.query.vrl.at(vp.sample(c.xi_vrl))));
    }
  }
  return *slot;
}

}  // namespace vrlis::bench

int main(int argc, char** argv) {
  using namespace vrlis::bench;
  // Our flags, taken out before Google Benchmark reads the rest.
  std::string queries, lanes = "widest";
  const std::string queries_flag = "--vrlis_queries=", lanes_flag = "--vrlis_lanes=";
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.rfind(queries_flag, 0) == 0) queries = arg.substr(queries_flag.size());
    else if (arg.rfind(lanes_flag, 0) == 0) lanes = arg.substr(lanes_flag.size());
    else argv[kept++] = argv[i];
  }
  if (lanes != "widest" && lanes != "built") {
    std::fprintf(stderr, "vrlis_bench: --vrlis_lanes must be widest or built, not %s\n", lanes.c_str());
    return 2;
  }
  vrlis::UseWidestLanes(lanes == "widest");
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("vrlis_pool", std::to_string(kPool));
  benchmark::AddCustomContext("vrlis_seed", std::to_string(kDefaultSeed));
  benchmark::AddCustomContext("vrlis_real", "float");
  benchmark::AddCustomContext("vrlis_lanes", vrlis::detail::Avx2LanesInUse() ? "avx2" : "built");
#if defined(__OPTIMIZE__) && defined(NDEBUG)
  benchmark::AddCustomContext("vrlis_build", "optimised, NDEBUG");
#else
  benchmark::AddCustomContext("vrlis_build", "NOT OPTIMISED: timings are meaningless");
#endif
  for (double g : kStudyG) PoolsFor(g);  // build every pool before timing anything
  RegisterVrlPoint();
  RegisterCamera();
  RegisterCameraSeparate();
  if (!queries.empty()) {
    std::string error;
    if (!RegisterSceneCamera(queries, &error)) {
      std::fprintf(stderr, "vrlis_bench: %s\n", error.c_str());
      return 2;
    }
  }
  RegisterFit();
  RegisterEstimator();
  RegisterGather();
  RegisterWork();
#ifdef VRLIS_BENCH_RENDERER
  RegisterRendererWork();
#endif
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
