// SceneCamera/<method>: the camera step (fit + sample_pdf) on the medium-to-medium queries a
// render really makes, read from a query log (vrl_render --dump-queries FILE; run
// vrlis_bench --vrlis_queries=FILE). The synthetic pools of Camera/ spread their queries
// evenly over configurations; a scene's are concentrated (on the bidirectional scene, long
// segments whose VRL points lie millimetres from the camera ray), and a sampler's cost can
// differ there: FullProduct's split search rejects most of them early.
#include "bench_common.hpp"

#include <vrlis_integration/query_log.hpp>

namespace vrlis::bench {
namespace {

// Each record's camera-step query at its VRL point for u = the record's golden-ratio
// number, and the camera step's u alike (no record is timed at one u only).
struct ScenePool {
  std::vector<SegmentQuery<float>> camera;
  std::vector<float> xi;
};

ScenePool MakeScenePool(const std::vector<vrlis::integration::QueryRecord>& records) {
  ScenePool pool;
  double xi = 0.5;
  for (const vrlis::integration::QueryRecord& r : records) {
    if (Validate(r.query) != QueryError::None) continue;
    xi = xi + 0.6180339887498949 - (xi + 0.6180339887498949 >= 1 ? 1 : 0);
    VrlPoint<float> vp(r.query);
    pool.camera.push_back(CameraStepQuery(r.query, r.query.vrl.at(vp.sample(float(xi)))));
    pool.xi.push_back(float(1 - xi));
  }
  return pool;
}

template <typename Sampler>
void SceneCamera(benchmark::State& state, const ScenePool& pool) {
  size_t i = 0;
  for (auto _ : state) {
    Sampler s(pool.camera[i]);
    SegmentSample<float> sample = s.sample_pdf(pool.xi[i]);
    benchmark::DoNotOptimize(sample);
    i = i + 1 == pool.camera.size() ? 0 : i + 1;
  }
  state.SetItemsProcessed(state.iterations());
}

template <typename... Entries>
void RegisterEach(const ScenePool& pool, Registry<Entries...>*) {
  ((void)benchmark::RegisterBenchmark((std::string("SceneCamera/") + std::string(Entries::kName)).c_str(),
                                      [&pool](benchmark::State& state) {
                                        SceneCamera<typename Entries::template Sampler<float>>(state, pool);
                                      }),
   ...);
}

}  // namespace

bool RegisterSceneCamera(const std::string& path, std::string* error) {
  std::optional<std::vector<vrlis::integration::QueryRecord>> records = vrlis::integration::ReadQueryLog(path, error);
  if (!records) return false;
  static const ScenePool pool = MakeScenePool(*records);
  if (pool.camera.empty()) {
    *error = "'" + path + "' holds no valid query";
    return false;
  }
  RegisterEach(pool, static_cast<SegmentSamplers*>(nullptr));
  return true;
}

}  // namespace vrlis::bench
