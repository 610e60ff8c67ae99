// vrlis_bench: the cost of one sample as a renderer pays it, with Google Benchmark.
//
//   Camera/<Sampler>/g:<g>     build the sampler from a query (the fit), sample, pdf
//   Estimator/<Sampler>/g:<g>  the whole medium-to-medium step without visibility: VrlPoint
//                              (fit, sample, pdf), the camera sampler (fit, sample, pdf), the
//                              integrand, f / (p1 p2)
//   Fit/<Sampler>/g:<g>        the fit alone (where Camera's time goes)
//   VrlPoint                   step one alone (fit, sample, pdf); independent of g
//
// Every benchmark cycles in order through a pool of 1024 random queries (the pairs of the
// accuracy study, seeded), so that no single warm branch is timed. Float throughout; each
// sampler is its concrete type (no run-time dispatch). One iteration is one sample.
// Standard flags apply: --benchmark_filter=Novak, --benchmark_format=json, ...
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "study/integrand.hpp"

namespace {

using namespace vrlis;
using namespace vrlis::study;
constexpr size_t kPool = 1024;  // a power of two: the index wraps with a mask

struct Pools {
  std::vector<Pair<float>> pairs;
  std::vector<SegmentQuery<float>> camera;  // each pair's camera query at its fixed VRL point
  std::vector<VrlPointQuery<float>> vrl;
};

const Pools& PoolsFor(double g) {
  static std::map<double, std::unique_ptr<Pools>> cache;
  auto& slot = cache[g];
  if (!slot) {
    slot = std::make_unique<Pools>();
    for (const Pair<double>& pd : MakePairs(kDefaultSeed, int(kPool), g)) {
      Pair<float> p = pd.as<float>();
      VrlPoint<float> vp(VrlQuery(p));
      slot->pairs.push_back(p);
      slot->vrl.push_back(VrlQuery(p));
      slot->camera.push_back(CameraQuery(p, VrlPointAt(p, vp.sample(p.xi_vrl))));
    }
  }
  return *slot;
}

template <typename Sampler>
void Camera(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  size_t i = 0;
  for (auto _ : state) {
    Sampler s(pools.camera[i]);
    float t = s.sample(pools.pairs[i].xi_cam);
    float pdf = s.pdf(t);
    benchmark::DoNotOptimize(t);
    benchmark::DoNotOptimize(pdf);
    i = (i + 1) & (kPool - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

// The fit alone, to see where Camera's time goes.
template <typename Sampler>
void Fit(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  size_t i = 0;
  for (auto _ : state) {
    Sampler s(pools.camera[i]);
    benchmark::DoNotOptimize(s);
    i = (i + 1) & (kPool - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

template <typename Sampler>
void Estimator(benchmark::State& state, double g) {
  const Pools& pools = PoolsFor(g);
  size_t i = 0;
  for (auto _ : state) {
    const Pair<float>& p = pools.pairs[i];
    VrlPoint<float> vp(VrlQuery(p));
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

void VrlPointStep(benchmark::State& state) {
  const Pools& pools = PoolsFor(0.0);
  size_t i = 0;
  for (auto _ : state) {
    VrlPoint<float> vp(pools.vrl[i]);
    float v = vp.sample(pools.pairs[i].xi_vrl);
    float pdf = vp.pdf(v);
    benchmark::DoNotOptimize(v);
    benchmark::DoNotOptimize(pdf);
    i = (i + 1) & (kPool - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

std::string GName(double g) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "g:%.2f", g);
  return buf;
}

template <typename Sampler>
void RegisterSampler(const char* name) {
  for (double g : kStudyG) {
    benchmark::RegisterBenchmark((std::string("Camera/") + name + "/" + GName(g)).c_str(),
                                 [g](benchmark::State& s) { Camera<Sampler>(s, g); });
    benchmark::RegisterBenchmark((std::string("Fit/") + name + "/" + GName(g)).c_str(),
                                 [g](benchmark::State& s) { Fit<Sampler>(s, g); });
    benchmark::RegisterBenchmark((std::string("Estimator/") + name + "/" + GName(g)).c_str(),
                                 [g](benchmark::State& s) { Estimator<Sampler>(s, g); });
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("vrlis_pool", std::to_string(kPool));
  benchmark::AddCustomContext("vrlis_seed", std::to_string(kDefaultSeed));
  benchmark::AddCustomContext("vrlis_real", "float");
#if defined(__OPTIMIZE__) && defined(NDEBUG)
  benchmark::AddCustomContext("vrlis_build", "optimised, NDEBUG");
#else
  benchmark::AddCustomContext("vrlis_build", "NOT OPTIMISED: timings are meaningless");
#endif
  benchmark::RegisterBenchmark("VrlPoint", VrlPointStep);
  RegisterSampler<Equiangular<float>>(kCameraSamplerNames[0]);
  RegisterSampler<Novak<float>>(kCameraSamplerNames[1]);
  RegisterSampler<CauchySum<float>>(kCameraSamplerNames[2]);
  RegisterSampler<CauchyMixture<float>>(kCameraSamplerNames[3]);
  RegisterSampler<FullProduct<float>>(kCameraSamplerNames[4]);
  static_assert(kCameraSamplerCount == 5, "register every camera sampler");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
