// vrlis_accuracy: relative variance of every camera sampler without noise, by quadrature.
//
// Synthetic mode (default): for each g in {-0.99, ..., 0.99} and a fixed, seeded set of
// random configurations (study/config.hpp; the same geometry for every g), computes
//   - the relative variance of the camera step alone, for the configuration's fixed VRL point;
//   - the relative variance of the whole two-step estimator (VRL point by VrlPoint, camera
//     point by the sampler, full integrand with transmittance);
//   - the same with VrlMarginal as step one ("whole_marginal" in the JSON, "wholM" rows;
//     VrlMarginal needs a finite camera segment, so unbounded ones are left out of it);
//     with --marginal-turn RAD, VrlMarginal fitted for the camera ray turned by RAD about its
//     origin and warped by the query's own VrlPoint: what sharing one fit between pixels
//     RAD apart would cost (docs/maths.md#vrl-marginal-shared);
// and prints the median and mean per g and sampler (a table, or JSON with --json).
//
// Scene mode (--queries FILE): the same on the gather queries a render wrote
// (vrl_render --dump-queries, vrlis_integration/query_log.hpp), with two means: unweighted,
// and weighted as the image weighs them. A query contributes w I to the image (w its
// weight in the log, I the integral of its integrand) and w^2 I^2 relvar to its variance,
// so the image-weighted relative variance is sum (w I)^2 relvar / sum (w I)^2. It also
// reports how concentrated those weights are and which queries carry the most.
//
// Largest weights (--queries FILE --largest-weights N): per gather method (every camera
// sampler with either step one), the largest weight f / (p1 p2) relative to the query's
// integral I over an N x N stratified grid of (u_vrl, u_camera), the largest over the
// queries (docs/stability.md). A sample maximum, so a lower bound of the supremum. I is the
// mean weight of the step-one-VrlPoint methods' grids (each an unbiased estimate of it; with
// N = 32 its relative error is far below the table's precision), so no quadrature is needed.
//
//   vrlis_accuracy [--pairs N] [--seed S] [--threads T] [--json FILE] [--inner-tol X] [--outer-tol X] [--marginal-turn RAD]
//   vrlis_accuracy --queries FILE [--seed S] [--threads T] [--json FILE] [--top N] ...
//   vrlis_accuracy --queries FILE --largest-weights N [--threads T] [--json FILE]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numeric>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>
#include <vrlis_integration/query_log.hpp>

#include "study/variance.hpp"

namespace {

using namespace vrlis::study;
constexpr int K = kCameraSamplerCount;
using PerSampler = std::array<double, K>;
using Json = nlohmann::ordered_json;

struct Result {
  PerSampler camera{}, whole{}, whole_marginal{};  // relative variances; whole_marginal NaN if undefined
  double camera_first = 0, whole_first = 0;        // the integrals (the query's contribution before its weight)
  double rel_error = 0;
  bool converged = true;
};

// The query's camera ray turned by `angle` about its origin (a neighbouring pixel's ray
// through a pinhole), towards the azimuth `index` picks about it (a golden-ratio sequence).
vrlis::MediumGatherQuery<double> Turned(vrlis::MediumGatherQuery<double> q, double angle, std::size_t index) {
  const vrlis::Vec3<double> d = q.camera.dir;
  const vrlis::Vec3<double> e1 = Normalize(Cross(d, std::abs(d.x) < 0.9 ? vrlis::Vec3<double>{1, 0, 0}
                                                                        : vrlis::Vec3<double>{0, 1, 0})),
                            e2 = Cross(d, e1);
  const double phi = 2 * vrlis::kPi<double> * std::fmod(0.6180339887498949 * double(index), 1.0);
  q.camera.dir = Normalize(std::cos(angle) * d + std::sin(angle) * (std::cos(phi) * e1 + std::sin(phi) * e2));
  return q;
}

// marginal_turn > 0: VrlMarginal fitted for the camera ray turned by that angle (Turned).
Result Evaluate(const Config<double>& c, std::size_t index, const QuadratureSettings& s, double marginal_turn) {
  const vrlis::MediumGatherQuery<double> fitted_for = Turned(c.query, marginal_turn, index);
  Moments cam = CameraStepMoments(c.query, c.xi_vrl, s),
          whole = WholeMoments(c.query, s, marginal_turn > 0 ? &fitted_for : nullptr);
  Result r;
  for (int k = 0; k < K; ++k) {
    r.camera[k] = cam.RelativeVariance(k);
    r.whole[k] = whole.RelativeVariance(k);
    r.whole_marginal[k] = whole.RelativeVarianceMarginal(k);
  }
  r.camera_first = cam.first;
  r.whole_first = whole.first;
  r.rel_error = std::max(cam.rel_error, whole.rel_error);
  r.converged = cam.converged && whole.converged;
  return r;
}

// Deterministic: each task writes its own slot; the thread count only changes the speed.
std::vector<Result> EvaluateAll(const std::vector<Config<double>>& configs, const QuadratureSettings& s,
                                double marginal_turn, int threads) {
  std::vector<Result> results(configs.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i; (i = next++) < configs.size();) results[i] = Evaluate(configs[i], i, s, marginal_turn);
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  return results;
}

// Where the issue of long segments lies (docs/accuracy_scenes.md): the closest points of
// the camera segment and the VRL, their distance h, and the camera segment's length beyond
// its closest point, both in mean free paths.
struct Closeness {
  double h_mfp = 0, beyond_mfp = 0;
  bool hard() const { return h_mfp < 0.05 && beyond_mfp > 3; }
};

Closeness ClosenessOf(const vrlis::MediumGatherQuery<double>& q) {
  const auto &c = q.camera;
  const auto& l = q.vrl;
  auto clamp_t = [&](double t) { return std::min(std::max(t, c.tmin), c.tmax); };
  auto clamp_v = [&](double v) { return std::min(std::max(v, 0.0), l.length); };
  // Alternating projections between the two segments converge to their closest points
  // (both are convex); a few rounds from the closest points of the lines are plenty here.
  vrlis::Vec3<double> d = l.origin - c.origin;
  double b = Dot(c.dir, l.dir), denom = 1 - b * b;
  double t = denom > 1e-12 ? (Dot(d, c.dir) - b * Dot(d, l.dir)) / denom : c.tmin;
  t = clamp_t(std::isfinite(t) ? t : c.tmin);
  double v = 0;
  for (int i = 0; i < 4; ++i) {
    v = clamp_v(Dot(c.at(t) - l.origin, l.dir));
    t = clamp_t(Dot(l.at(v) - c.origin, c.dir));
  }
  double sigma_t = q.medium.sigma_t;
  return {sigma_t * Length(l.at(v) - c.at(t)), sigma_t * (c.tmax - t)};
}

struct Summary {
  double median = 0, mean = 0, weighted = 0;
  int best = 0;  // configurations where this sampler has the lowest relative variance (ties count for each)
  int count = 0;  // configurations where it is defined
};

double Median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  std::size_t n = x.size();
  return n == 0 ? std::nan("") : n % 2 ? x[n / 2] : (x[n / 2 - 1] + x[n / 2]) / 2;
}

// Per sampler over the results where the relative variance is defined; `weight` (may be
// empty) gives the weighted mean.
std::array<Summary, K> Summarise(const std::vector<Result>& rows, PerSampler Result::*field,
                                 const std::vector<double>& weight) {
  std::array<Summary, K> out;
  for (int k = 0; k < K; ++k) {
    std::vector<double> x;
    double wsum = 0, wx = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      double v = (rows[i].*field)[k];
      if (!std::isfinite(v)) continue;
      x.push_back(v);
      if (!weight.empty()) {
        wsum += weight[i];
        wx += weight[i] * v;
      }
    }
    out[k].count = int(x.size());
    out[k].median = Median(x);
    out[k].mean = x.empty() ? std::nan("") : std::accumulate(x.begin(), x.end(), 0.0) / double(x.size());
    out[k].weighted = wsum > 0 ? wx / wsum : std::nan("");
  }
  for (const Result& r : rows) {  // ties (g = 0: every phase-only sampler is equiangular) credit all
    const PerSampler& v = r.*field;
    if (!std::isfinite(v[0])) continue;
    double lowest = *std::min_element(v.begin(), v.end());
    for (int k = 0; k < K; ++k)
      if (v[k] <= lowest + 1e-9 * std::abs(lowest)) out[k].best++;
  }
  return out;
}

constexpr struct {
  const char* json;
  const char* row;
  PerSampler Result::*field;
} kSteps[] = {{"camera", "cam", &Result::camera},
              {"whole", "whole", &Result::whole},
              {"whole_marginal", "wholM", &Result::whole_marginal}};

std::string SamplerName(int k) { return std::string(vrlis::Name(vrlis::kSegmentSamplers[std::size_t(k)])); }

void PrintHeader(bool weighted) {
  std::printf("%-6s %-5s", "g", "step");
  for (int k = 0; k < K; ++k) std::printf(" | %-*s", weighted ? 35 : 26, SamplerName(k).c_str());
  std::printf("\n%-6s %-5s", "", "");
  for (int k = 0; k < K; ++k) {
    std::printf(" | %8s %8s %8s", "median", "mean", weighted ? "weighted" : "best");
    if (weighted) std::printf(" %8s", "best");
  }
  std::printf("\n");
}

// Prints one row per step and returns the steps' summaries as JSON; the camera step is
// weighted by camera_weight, the whole estimator by whole_weight (both empty: unweighted).
Json Report(double g, const std::vector<Result>& rows, const std::vector<double>& camera_weight,
            const std::vector<double>& whole_weight) {
  Json entry;
  for (const auto& step : kSteps) {
    const std::vector<double>& weight = step.field == &Result::camera ? camera_weight : whole_weight;
    auto summary = Summarise(rows, step.field, weight);
    std::printf("%-6.2f %-5s", g, step.row);
    for (int k = 0; k < K; ++k) {
      const Summary& s = summary[std::size_t(k)];
      std::printf(" | %8.4g %8.4g", s.median, s.mean);
      if (!weight.empty()) std::printf(" %8.4g", s.weighted);
      std::printf(" %8d", s.best);
      Json j = {{"median", s.median}, {"mean", s.mean}, {"best", s.best}, {"count", s.count}};
      if (!weight.empty()) j["weighted"] = s.weighted;
      entry[step.json][SamplerName(k)] = j;
    }
    std::printf("\n");
  }
  double worst = 0;
  int unconverged = 0;
  for (const Result& r : rows) {
    worst = std::max(worst, r.rel_error);
    unconverged += !r.converged;
  }
  entry["max_rel_error"] = worst;
  entry["unconverged"] = unconverged;
  if (unconverged)
    std::printf("  warning: %d configurations did not reach the tolerance within the evaluation budget (worst "
                "estimated relative error %.1e; the G7-K15 estimate is pessimistic)\n",
                unconverged, worst);
  return entry;
}

// The hard class's share of the configurations; with weights, its share of the weights
// (w I)^2 and of the image's second moment (w I)^2 (1 + relvar) of the whole estimator.
Json HardShare(const std::vector<Config<double>>& configs, const std::vector<Result>& rows,
               const std::vector<double>& weight) {
  int hard = 0;
  double whard = 0, wall = 0;
  PerSampler mhard{}, mall{};
  for (std::size_t i = 0; i < configs.size(); ++i) {
    bool h = ClosenessOf(configs[i].query).hard();
    hard += h;
    if (weight.empty()) continue;
    wall += weight[i];
    whard += h ? weight[i] : 0;
    for (int k = 0; k < K; ++k) {
      double m = weight[i] * (1 + rows[i].whole[std::size_t(k)]);
      mall[std::size_t(k)] += m;
      mhard[std::size_t(k)] += h ? m : 0;
    }
  }
  Json j = {{"count", hard}, {"fraction", double(hard) / double(configs.size())}};
  if (wall > 0) {
    j["weight_fraction"] = whard / wall;
    for (int k = 0; k < K; ++k) j["second_moment_fraction"][SamplerName(k)] = mhard[std::size_t(k)] / mall[std::size_t(k)];
  }
  return j;
}

[[noreturn]] void Usage(int code) {
  std::fprintf(code ? stderr : stdout,
               "usage: vrlis_accuracy [--pairs N=256] [--seed S] [--threads T=2] [--json FILE]\n"
               "                      [--inner-tol X=1e-9] [--outer-tol X=1e-7] [--marginal-turn RAD=0]\n"
               "       vrlis_accuracy --queries FILE [--top N=8] [--seed S] [--threads T] [--json FILE] ...\n"
               "       vrlis_accuracy --queries FILE --largest-weights N [--threads T] [--json FILE]\n");
  std::exit(code);
}

[[noreturn]] void Fail(const std::string& message) {
  std::fprintf(stderr, "vrlis_accuracy: error: %s\n", message.c_str());
  std::exit(1);
}

bool WriteJson(const std::string& path, const Json& out) {
  if (path.empty()) return true;
  std::ofstream f(path);
  f << out.dump(2) << "\n";
  return bool(f);
}

int RunSynthetic(int pairs, std::uint64_t seed, int threads, const QuadratureSettings& settings, double marginal_turn,
                 const std::string& json_path) {
  auto start = std::chrono::steady_clock::now();
  Json out;
  out["tool"] = "vrlis_accuracy";
  out["seed"] = seed;
  out["pairs"] = pairs;
  out["inner_tol"] = settings.inner_tol;
  out["outer_tol"] = settings.outer_tol;
  out["marginal_turn"] = marginal_turn;
  out["medium"] = kSyntheticDescription;
  for (auto m : vrlis::kSegmentSamplers) out["samplers"].push_back(vrlis::Name(m));
  out["results"] = Json::array();
  std::vector<std::vector<Result>> results;
  for (double g : kStudyG) results.push_back(EvaluateAll(MakeConfigs(seed, pairs, g), settings, marginal_turn, threads));
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out["seconds"] = seconds;
  // The geometry is the same for every g, so the hard class is too.
  out["hard_class"] = HardShare(MakeConfigs(seed, pairs, 0), {}, {});

  std::printf("Relative variance by quadrature, %d configurations per g (seed %llu), %.1f s\n", pairs,
              static_cast<unsigned long long>(seed), seconds);
  PrintHeader(false);
  for (std::size_t gi = 0; gi < std::size(kStudyG); ++gi) {
    Json entry = {{"g", kStudyG[gi]}};
    entry.update(Report(kStudyG[gi], results[gi], {}, {}));
    // The whole estimator with VrlPoint over the configurations where VrlMarginal is defined
    // (bounded camera segments), to compare the two steps one on the same configurations.
    std::vector<Result> bounded;
    for (const Result& r : results[gi])
      if (std::isfinite(r.whole_marginal[0])) bounded.push_back(r);
    auto summary = Summarise(bounded, &Result::whole, {});
    for (int k = 0; k < K; ++k)
      entry["whole_bounded"][SamplerName(k)] = {{"median", summary[std::size_t(k)].median},
                                                {"mean", summary[std::size_t(k)].mean},
                                                {"best", summary[std::size_t(k)].best},
                                                {"count", summary[std::size_t(k)].count}};
    out["results"].push_back(entry);
  }
  if (!WriteJson(json_path, out)) Fail("cannot write " + json_path);
  return 0;
}

int RunQueries(const std::string& path, int top, std::uint64_t seed, int threads, const QuadratureSettings& settings,
               double marginal_turn,
               const std::string& json_path) {
  std::string error;
  auto records = vrlis::integration::ReadQueryLog(path, &error);
  if (!records) Fail(error);
  if (records->empty()) Fail("'" + path + "' holds no queries");
  // The camera step's fixed VRL point: a seeded uniform per query.
  Rng rng(seed);
  std::vector<Config<double>> configs;
  for (const vrlis::integration::QueryRecord& r : *records) {
    Config<float> c{r.query, 0.5f, 0.5f};
    configs.push_back(c.as<double>());
    configs.back().xi_vrl = rng.uniform();
  }
  double g = configs[0].query.medium.g;
  for (const Config<double>& c : configs)
    if (c.query.medium.g != g) Fail("'" + path + "' mixes media of different g");

  auto start = std::chrono::steady_clock::now();
  std::vector<Result> rows = EvaluateAll(configs, settings, marginal_turn, threads);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The image's weights: (w I)^2, with I the whole estimator's (or the camera step's) integral.
  std::vector<double> weight(rows.size()), camera_weight(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    double w = (*records)[i].weight;
    weight[i] = w * w * rows[i].whole_first * rows[i].whole_first;
    camera_weight[i] = w * w * rows[i].camera_first * rows[i].camera_first;
  }
  double total = std::accumulate(weight.begin(), weight.end(), 0.0);
  if (!(total > 0)) Fail("every query of '" + path + "' has zero weight");
  std::vector<std::size_t> order(rows.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return weight[a] > weight[b]; });
  double sum2 = 0;
  for (double w : weight) sum2 += w * w;

  Json out;
  out["tool"] = "vrlis_accuracy";
  out["queries"] = path;
  out["records"] = rows.size();
  out["seed"] = seed;
  out["inner_tol"] = settings.inner_tol;
  out["outer_tol"] = settings.outer_tol;
  out["marginal_turn"] = marginal_turn;
  out["g"] = g;
  for (auto m : vrlis::kSegmentSamplers) out["samplers"].push_back(vrlis::Name(m));
  out["seconds"] = seconds;
  // Effective number of queries under the image's weights (Kish): how many carry the image.
  out["effective_queries"] = total * total / sum2;
  out["hard_class"] = HardShare(configs, rows, weight);

  std::printf("Relative variance by quadrature of %zu gather queries from %s (g %.2f), %.1f s\n", rows.size(),
              path.c_str(), g, seconds);
  std::printf("Effective number of queries under the image's weights: %.1f; hard class (sigma_t h < 0.05, more "
              "than 3 mfp beyond the closest point): %.1f%% of queries, %.1f%% of the weight\n",
              out["effective_queries"].get<double>(), 100 * out["hard_class"]["fraction"].get<double>(),
              100 * out["hard_class"]["weight_fraction"].get<double>());
  std::printf("Hard class's share of the image's second moment of the whole estimator:");
  for (int k = 0; k < K; ++k)
    std::printf(" %s %.1f%%", SamplerName(k).c_str(),
                100 * out["hard_class"]["second_moment_fraction"][SamplerName(k)].get<double>());
  std::printf("\n");
  PrintHeader(true);
  // The camera step weighs each query by its camera-step integral at the fixed VRL point.
  Json entry = {{"g", g}};
  entry.update(Report(g, rows, camera_weight, weight));
  out["results"] = Json::array({entry});

  std::printf("Largest image weights (share of sum (w I)^2):\n");
  out["largest"] = Json::array();
  for (int n = 0; n < std::min<int>(top, int(rows.size())); ++n) {
    std::size_t i = order[std::size_t(n)];
    const auto& q = configs[i].query;
    Closeness c = ClosenessOf(q);
    double st = q.medium.sigma_t;
    Json j = {{"index", i},
              {"share", weight[i] / total},
              {"sigma_t", st},
              {"h_mfp", c.h_mfp},
              {"beyond_mfp", c.beyond_mfp},
              {"camera_mfp", st * (q.camera.tmax - q.camera.tmin)},
              {"vrl_mfp", st * q.vrl.length}};
    std::printf("  #%zu share %.3g: sigma_t %.3g, h %.3g mfp, %.3g mfp beyond, camera %.3g mfp, VRL %.3g mfp; "
                "whole rel. var.",
                i, weight[i] / total, st, c.h_mfp, c.beyond_mfp, st * (q.camera.tmax - q.camera.tmin),
                st * q.vrl.length);
    for (int k = 0; k < K; ++k) {
      std::printf(" %s %.3g", SamplerName(k).c_str(), rows[i].whole[std::size_t(k)]);
      j["whole"][SamplerName(k)] = rows[i].whole[std::size_t(k)];
    }
    std::printf("\n");
    out["largest"].push_back(j);
  }
  double top_share = 0;
  for (std::size_t n = 0; n < std::min<std::size_t>(std::size_t(top), order.size()); ++n) top_share += weight[order[n]];
  out["largest_share"] = top_share / total;
  if (!WriteJson(json_path, out)) Fail("cannot write " + json_path);
  return 0;
}

int RunLargestWeights(const std::string& path, int grid, int threads, const std::string& json_path) {
  std::string error;
  auto records = vrlis::integration::ReadQueryLog(path, &error);
  if (!records) Fail(error);
  if (records->empty()) Fail("'" + path + "' holds no queries");
  std::vector<vrlis::GatherSamplers> methods;
  for (auto vrl : vrlis::kVrlSamplers)
    for (auto camera : vrlis::kSegmentSamplers) methods.push_back({camera, vrl});
  // Per query and method: the largest weight and the sum of weights over the grid.
  std::vector<std::vector<double>> largest(records->size()), sum(records->size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i; (i = next++) < records->size();) {
      vrlis::MediumGatherQuery<double> q = Config<float>{(*records)[i].query, 0.5f, 0.5f}.as<double>().query;
      for (vrlis::GatherSamplers m : methods) {
        double worst = 0, total = 0;
        for (int a = 0; a < grid; ++a)
          for (int b = 0; b < grid; ++b) {
            double w = vrlis::SampleMediumGather(m, q, (a + 0.5) / grid, (b + 0.5) / grid).weight;
            worst = std::max(worst, w);
            total += w;
          }
        largest[i].push_back(worst);
        sum[i].push_back(total);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();

  std::vector<double> worst(methods.size(), 0.0);
  int used = 0;
  for (std::size_t i = 0; i < records->size(); ++i) {
    double total = 0;
    int count = 0;
    for (std::size_t k = 0; k < methods.size(); ++k)
      if (methods[k].vrl == vrlis::VrlSamplers::Of<vrlis::VrlPointEntry>()) {
        total += sum[i][k];
        count += grid * grid;
      }
    double integral = total / count;
    if (!(integral > 0)) continue;  // no method finds anything: nothing to weigh against
    ++used;
    for (std::size_t k = 0; k < methods.size(); ++k) worst[k] = std::max(worst[k], largest[i][k] / integral);
  }
  Json out = {{"tool", "vrlis_accuracy"}, {"queries", path}, {"records", records->size()}, {"weighed", used},
              {"grid", grid}};
  std::printf("Largest weight f / (p1 p2 I) over %d queries of %s, %d x %d stratified pairs each:\n", used, path.c_str(),
              grid, grid);
  for (std::size_t k = 0; k < methods.size(); ++k) {
    out["largest_weight"][vrlis::Name(methods[k])] = worst[k];
    std::printf("  %-28s %.3g\n", vrlis::Name(methods[k]).c_str(), worst[k]);
  }
  if (!WriteJson(json_path, out)) Fail("cannot write " + json_path);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int pairs = 256, threads = 2, top = 8, largest_weights = 0;
  std::uint64_t seed = kDefaultSeed;
  std::string json_path, queries;
  QuadratureSettings settings;
  double marginal_turn = 0;
  settings.inner_tol = 1e-9;
  settings.outer_tol = 1e-7;
  auto number = [](const char* text, auto parse) {
    char* end = nullptr;
    auto x = parse(text, &end);
    if (!*text || *end) Usage(2);
    return x;
  };
  auto to_int = [&](const char* s) { return int(number(s, [](const char* t, char** e) { return std::strtol(t, e, 10); })); };
  auto to_double = [&](const char* s) { return number(s, [](const char* t, char** e) { return std::strtod(t, e); }); };
  for (int i = 1; i < argc; ++i) {
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) Usage(2);
      return argv[++i];
    };
    if (!std::strcmp(argv[i], "--pairs")) pairs = to_int(value());
    else if (!std::strcmp(argv[i], "--seed"))
      seed = number(value(), [](const char* t, char** e) { return std::strtoull(t, e, 10); });
    else if (!std::strcmp(argv[i], "--threads")) threads = to_int(value());
    else if (!std::strcmp(argv[i], "--json")) json_path = value();
    else if (!std::strcmp(argv[i], "--queries")) queries = value();
    else if (!std::strcmp(argv[i], "--top")) top = to_int(value());
    else if (!std::strcmp(argv[i], "--largest-weights")) largest_weights = to_int(value());
    else if (!std::strcmp(argv[i], "--inner-tol")) settings.inner_tol = to_double(value());
    else if (!std::strcmp(argv[i], "--outer-tol")) settings.outer_tol = to_double(value());
    else if (!std::strcmp(argv[i], "--marginal-turn")) marginal_turn = to_double(value());
    else if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) Usage(0);
    else Usage(2);
  }
  if (pairs < 1 || threads < 1 || top < 0 || largest_weights < 0 || (largest_weights > 0 && queries.empty()) || !(settings.inner_tol > 0) || !(settings.outer_tol > 0) || !(marginal_turn >= 0 && marginal_turn < 1)) Usage(2);
  if (largest_weights > 0) return RunLargestWeights(queries, largest_weights, threads, json_path);
  return queries.empty() ? RunSynthetic(pairs, seed, threads, settings, marginal_turn, json_path)
                         : RunQueries(queries, top, seed, threads, settings, marginal_turn, json_path);
}
