// Hypotheses: the effort control (vrlis/effort/, vrlis/gather/gather_vrls.hpp) keeps the gather
// unbiased and its weights finite, and its decisions follow the price.
// - Roulette (every q < 1) and splitting (every q > 1) give the mean of the gather without
//   the control, within 4 standard errors; the same runs with the 1 / q weight left out
//   (a sabotage) are rejected.
// - q: 1 with the control off or no price; the floor for a price near zero (gathers whose
//   variance is nothing next to the image's), the ceiling for a huge one; never 0 or NaN.
// - Every weight handed to the renderer is finite and at most 1 / floor, for prices and
//   queries at their extremes.
// - The bounds of effort.hpp are at or above the gather's mean; batched in vector lanes they
//   are the one-at-a-time bounds to rounding.
// - An effort model replaces auto's rule by its sampler and leaves every other sampler.
// - With VrlMarginal as step one and a threshold of scores, the gathers whose score reaches it
//   take the fit's density and the others VrlPoint's (each gather's density is one of the two
//   a one-at-a-time sampler gives it, so the estimator stays unbiased); ScoreOctaves' threshold
//   fits at most the share of the scores asked for, and one octave lower more.
#include <catch2/catch.hpp>
#include <vrlis/core/running_moments.hpp>
#include <vrlis/gather/gather_vrls.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "extern_gathers.hpp"

namespace {

using Real = float;

struct Setup {
  vrlis::RaySegment<Real> camera{{0, 0, 0}, {0, 0, -1}, Real(0.5), Real(6)};
  vrlis::Medium<Real> medium = vrlis::Medium<Real>::FromScatteringExtinction(Real(0.3), Real(0.5), Real(0.8));
  std::vector<vrlis::VrlSegment<Real>> vrls;
  std::vector<Real> weights;
  vrlis::GatherSamplers method = vrlis::FixedSamplers<vrlis::EquiangularEntry>{};
};

Setup MakeSetup() {
  Setup s;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 12; ++i) {
    vrlis::Vec3<Real> origin{Real(1 + std::abs(2 * u(rng))) * (i % 2 ? 1 : -1), Real(2 * u(rng)), Real(-1 - 3 * std::abs(u(rng)))};
    vrlis::Vec3<Real> dir = vrlis::Normalize(vrlis::Vec3<Real>{Real(u(rng)), Real(u(rng)), Real(u(rng))});
    s.vrls.push_back({origin, dir, Real(0.5 + 2 * std::abs(u(rng)))});
    s.weights.push_back(Real(std::pow(10.0, 2 * u(rng))));
  }
  return s;
}

// Every one-call gather of this file goes through this one instantiation: each distinct visitor
// type would compile every sampler pair again (a minute of build apiece).
void Gather(vrlis::GatherSamplers method, const Setup& s, const vrlis::EffortSettings& effort, const Real* weights,
            int count, const std::function<Real()>& uniform,
            const std::function<void(int, const vrlis::GatherSample<Real>&, Real)>& visit) {
  vrlis::GatherMediumVrls(method, s.camera, s.medium, s.vrls.data(), count, uniform, visit,
                          vrlis::EffortCall<Real>{effort, weights});
}

struct Moments {
  double mean = 0, se = 0;
};

// The gather's sum over the setup's VRLs, `runs` times; with `sabotage` the effort weight is
// left out, and every weight is multiplied by `scale`.
Moments Estimate(const Setup& s, const vrlis::EffortSettings& effort, int runs, bool sabotage = false,
                 double scale = 1) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> u(0, 1);
  double sum = 0, sum_sq = 0;
  for (int r = 0; r < runs; ++r) {
    double x = 0;
    Gather(s.method, s, effort, s.weights.data(), int(s.vrls.size()), [&] { return u(rng); },
           [&](int i, const vrlis::GatherSample<Real>& g, Real w) {
             x += scale * double(s.weights[std::size_t(i)]) * g.weight * (sabotage ? 1 : w);
           });
    sum += x;
    sum_sq += x * x;
  }
  double mean = sum / runs;
  return {mean, std::sqrt((sum_sq / runs - mean * mean) / (runs - 1))};
}

double Z(const Moments& a, const Moments& b) { return std::abs(a.mean - b.mean) / std::hypot(a.se, b.se); }

// The smallest and largest predicted contribution w x bound over the setup.
std::pair<double, double> BoundRange(const Setup& s) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (std::size_t i = 0; i < s.vrls.size(); ++i) {
    double b = s.weights[i] * vrlis::MediumGatherBound(s.camera, s.vrls[i], s.medium);
    lo = std::min(lo, b), hi = std::max(hi, b);
  }
  return {lo, hi};
}

}  // namespace

TEST_CASE("roulette and splitting keep the gather unbiased but not without 1 / q", "[gather][effort]") {
  const Setup s = MakeSetup();
  const Moments off = Estimate(s, {}, 40000);
  auto [lo, hi] = BoundRange(s);
  vrlis::EffortSettings roulette{true, vrlis::Sqr(0.8 / hi)};  // every q at most 0.8
  vrlis::EffortSettings split{true, vrlis::Sqr(1.5 / lo)};     // every q at least 1.5
  for (const auto& [name, effort, runs] : {std::tuple{"roulette", roulette, 40000}, std::tuple{"splitting", split, 10000}}) {
    INFO(name);
    const Moments on = Estimate(s, effort, runs);
    INFO("off " << off.mean << " +- " << off.se << ", on " << on.mean << " +- " << on.se);
    CHECK(Z(on, off) < 4);
    const Moments sabotaged = Estimate(s, effort, runs, true);
    INFO("sabotaged " << sabotaged.mean << " +- " << sabotaged.se);
    CHECK(Z(sabotaged, off) > 4);
  }
}

// A call taken at rate 0.3, its gathers 1 / 0.3 times as often: the mean is kept, and
// without the call's 1 / rate in the weights (a sabotage) it is not.
TEST_CASE("a call taken with a probability keeps the gather unbiased but not without 1 / rate",
          "[gather][effort]") {
  const Setup s = MakeSetup();
  const Moments off = Estimate(s, {}, 40000);
  const double hi = BoundRange(s).second;
  vrlis::EffortSettings e{true, vrlis::Sqr(0.8 / hi)};  // every q at most 0.8 overall
  e.call_demand = 0.3;
  REQUIRE(vrlis::EffortCallRate(e) == 0.3);
  const Moments on = Estimate(s, e, 60000);
  INFO("off " << off.mean << " +- " << off.se << ", on " << on.mean << " +- " << on.se);
  CHECK(Z(on, off) < 4);
  const Moments sabotaged = Estimate(s, e, 60000, false, 0.3);
  INFO("sabotaged " << sabotaged.mean << " +- " << sabotaged.se);
  CHECK(Z(sabotaged, off) > 4);
}

// MediumGatherReadsVrls predicts from a call's first number whether it reads its VRLs: a call
// it says does not draws that one number alone and visits nothing, even with its VRLs and
// weights NaN (were they read, NaN bounds take every gather once); one it says does draws more.
TEST_CASE("a call reads its VRLs exactly where MediumGatherReadsVrls says", "[gather][effort]") {
  const Setup s = MakeSetup();
  Setup poisoned = s;
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  for (auto& v : poisoned.vrls) v = {{nan, nan, nan}, {nan, nan, nan}, nan};
  std::fill(poisoned.weights.begin(), poisoned.weights.end(), nan);
  vrlis::EffortSettings e{true, vrlis::Sqr(0.8 / BoundRange(s).second)};
  e.call_demand = 0.3;
  std::mt19937 rng(17);
  std::uniform_real_distribution<Real> u(0, 1);
  int skipped = 0, read = 0, wrong = 0;
  for (int run = 0; run < 400; ++run) {
    std::mt19937 peek = rng;
    const bool reads = vrlis::MediumGatherReadsVrls(s.method, vrlis::EffortCall<Real>{e, nullptr}, double(u(peek)));
    const Setup& given = reads ? s : poisoned;
    int draws = 0, visits = 0;
    Gather(s.method, given, e, given.weights.data(), int(given.vrls.size()), [&] { return ++draws, u(rng); },
           [&](int, const vrlis::GatherSample<Real>&, Real) { ++visits; });
    wrong += reads ? draws <= 1 : draws != 1 || visits != 0;
    (reads ? read : skipped) += 1;
  }
  INFO(skipped << " calls not read, " << read << " read, " << wrong << " mispredicted");
  CHECK(wrong == 0);
  CHECK(skipped > 200);  // about 70% at rate 0.3
  CHECK(read > 60);
  // The control off: every call reads.
  CHECK(vrlis::MediumGatherReadsVrls(s.method, vrlis::EffortCall<Real>{}, 0.99));
}

TEST_CASE("q follows the price, between the floor and the ceiling", "[gather][effort]") {
  vrlis::EffortSettings e;
  CHECK(vrlis::EffortQ(e, 1.0) == 1);  // off
  e.on = true;
  CHECK(vrlis::EffortQ(e, 1.0) == 1);  // no price learned yet
  e.price = std::numeric_limits<double>::quiet_NaN();
  CHECK(vrlis::EffortQ(e, 1.0) == 1);
  e.price = 1e-12;  // the image's variance is far above this gather's: the floor
  CHECK(vrlis::EffortQ(e, 1.0) == e.floor);
  e.price = 1e12;
  CHECK(vrlis::EffortQ(e, 1.0) == e.ceiling);
  e.price = 4;
  CHECK(vrlis::EffortQ(e, 1.0) == Approx(2));
  CHECK(vrlis::EffortQ(e, 0.01) == Approx(0.2));
  CHECK(vrlis::EffortQ(e, 0.0) == e.floor);  // never 0: a bound that rounds to 0 must not drop a gather
  CHECK(vrlis::EffortQ(e, std::numeric_limits<double>::infinity()) == e.ceiling);
  CHECK(vrlis::EffortQ(e, std::numeric_limits<double>::quiet_NaN()) == 1);
  double previous = 0;
  for (double price = 1e-6; price < 1e6; price *= 3) {
    e.price = price;
    double q = vrlis::EffortQ(e, 1.0);
    CHECK(q >= previous);
    previous = q;
  }
  // Splitting reduces only the within share: above one sample the demand shrinks by
  // sqrt(within), never below one; roulette keeps the whole second moment.
  e.price = 1;
  e.within = 0.25;
  CHECK(vrlis::EffortQ(e, 64.0) == Approx(4));
  CHECK(vrlis::EffortQ(e, 2.25) == 1);
  CHECK(vrlis::EffortQ(e, 0.25) == Approx(0.5));
  e.within = 1;
  CHECK(vrlis::EffortQ(e, 64.0) == Approx(8));
  // A call's rate: its demand between the floor and one; 1 without a price or a demand.
  e.call_demand = 0.3;
  CHECK(vrlis::EffortCallRate(e) == 0.3);
  e.call_demand = 1e-9;
  CHECK(vrlis::EffortCallRate(e) == e.floor);
  e.call_demand = 7;
  CHECK(vrlis::EffortCallRate(e) == 1);
  e.call_demand = std::numeric_limits<double>::quiet_NaN();
  CHECK(vrlis::EffortCallRate(e) == 1);
  e.call_demand = 0.3;
  e.price = 0;
  CHECK(vrlis::EffortCallRate(e) == 1);
  e.price = 1;
  // Stochastic rounding: q samples on average.
  int total = 0;
  for (int k = 0; k < 1000; ++k) total += vrlis::EffortSamples(2.3, (k + 0.5) / 1000);
  CHECK(total == 2300);
}

TEST_CASE("effort weights are finite and at most 1 / floor at extreme prices and queries", "[gather][effort]") {
  Setup s = MakeSetup();
  s.vrls.push_back({{0, 0, -2}, {1, 0, 0}, Real(1e-5)});                                    // tiny
  s.vrls.push_back({{-1, 0, -2}, {1, 0, 0}, Real(2)});                                      // crosses the camera line
  s.vrls.push_back({{Real(0.5), 0, -1}, {0, 0, -1}, Real(3)});                              // parallel to it
  s.weights.insert(s.weights.end(), {Real(1), Real(1e30), Real(0)});
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(0, 1);
  for (double price : {0.0, 1e-30, 1.0, 1e30, std::numeric_limits<double>::infinity(),
                       std::numeric_limits<double>::quiet_NaN()}) {
    vrlis::EffortSettings e{true, price};
    for (int r = 0; r < 50; ++r)
      Gather(s.method, s, e, s.weights.data(), int(s.vrls.size()),
             [&] { return u(rng); }, [&](int, const vrlis::GatherSample<Real>& g, Real w) {
               REQUIRE(std::isfinite(w));
               REQUIRE(w > 0);
               REQUIRE(w <= 1 / e.floor * (1 + 1e-6));
               REQUIRE(std::isfinite(g.weight));
             });
  }
}

// The bounds on random configurations in double: the gather's mean (by the accurate
// estimator, 3 standard errors of slack) at or below the bound, the bound at or below its
// quick form, and a tenth of the medium bound (half of the surface one) broken somewhere:
// the test has power (the tightest cases reach 0.17 and 0.79 of their bounds).
TEST_CASE("the gather bounds are at or above the gathers' means, the quick ones above them", "[gather][effort]") {
  const auto method = *vrlis::ParseGatherSamplers("full-product+marginal");
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  auto direction = [&] {
    double z = 2 * u(rng) - 1, phi = 2 * vrlis::kPi<double> * u(rng), r = std::sqrt(1 - z * z);
    return vrlis::Vec3<double>{r * std::cos(phi), r * std::sin(phi), z};
  };
  int tight_medium = 0, tight_surface = 0;
  for (int c = 0; c < 120; ++c) {
    const double g = (c % 2 ? 1 : -1) * (0.3 + 0.3 * (c / 2 % 3));
    const double sigma_s = 0.3 + 0.5 * u(rng), sigma_t = 0.9 + 0.5 * u(rng);
    const auto medium = vrlis::Medium<double>::FromScatteringExtinction(g, sigma_s, sigma_t);
    const vrlis::RaySegment<double> camera{{0, 0, 0}, direction(), 0.2 * u(rng), 0.5 + 4 * u(rng)};
    const vrlis::VrlSegment<double> vrl{{4 * u(rng) - 2, 4 * u(rng) - 2, 4 * u(rng) - 2}, direction(), 0.3 + 3 * u(rng)};
    const vrlis::Vec3<double> point{4 * u(rng) - 2, 4 * u(rng) - 2, 4 * u(rng) - 2}, normal = direction();
    vrlis::RunningMoments medium_mean, surface_mean;
    for (int k = 0; k < 20000; ++k) {
      double u1 = u(rng), u2 = u(rng), u3 = u(rng);
      medium_mean.add(vrlis::SampleMediumGather(method, vrlis::MediumGatherQuery<double>{camera, vrl, medium}, u1, u2).weight);
      surface_mean.add(vrlis::SampleSurfaceGather(method.segment, vrlis::SurfaceGatherQuery<double>{point, normal, vrl, medium}, u3).weight);
    }
    const double medium_bound = vrlis::MediumGatherBound(camera, vrl, medium);
    const double surface_bound = vrlis::SurfaceGatherBound(point, normal, vrl, medium);
    INFO("configuration " << c << ", g " << g);
    CHECK(medium_mean.mean() - 3 * medium_mean.standard_error() <= medium_bound);
    CHECK(surface_mean.mean() - 3 * surface_mean.standard_error() <= surface_bound);
    CHECK(medium_bound <= vrlis::MediumGatherQuickBound(camera, vrl, medium) * (1 + 1e-9));
    CHECK(surface_bound <= vrlis::SurfaceGatherQuickBound(point, normal, vrl, medium) * (1 + 1e-9));
    tight_medium += medium_mean.mean() - 3 * medium_mean.standard_error() > medium_bound / 10;
    tight_surface += surface_mean.mean() - 3 * surface_mean.standard_error() > surface_bound / 2;
  }
  CHECK(tight_medium > 0);
  CHECK(tight_surface > 0);
}

namespace {
// Every sample the medium gather hands over for `method` and `effort` in 200 calls, from one stream.
std::vector<std::pair<int, Real>> Samples(const Setup& s, vrlis::GatherSamplers method, const vrlis::EffortSettings& effort) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(0, 1);
  std::vector<std::pair<int, Real>> out;
  for (int call = 0; call < 200; ++call)
    Gather(method, s, effort, s.weights.data(), int(s.vrls.size()),
           [&] { return u(rng); },
           [&](int i, const vrlis::GatherSample<Real>& g, Real w) { out.push_back({i, g.weight * w}); });
  std::sort(out.begin(), out.end());
  return out;
}
}  // namespace

// A call that does not decide (EffortSettings::decide false) takes every gather once with
// weight 1, sample for sample as without the control, at any price; with `auto` and the
// cheapest model, the mixture or the accurate one asked for, that model's samples. The same
// prices change the samples of a call that decides (so the flag is what keeps them).
TEST_CASE("a call that does not decide takes every gather once, as without the control", "[gather][effort]") {
  Setup s = MakeSetup();
  auto [lo, hi] = BoundRange(s);
  const auto automatic = *vrlis::ParseGatherSamplers("auto");
  // Every demand at the floor, spread around one, above the accurate tier.
  for (double price : {vrlis::Sqr(0.04 / hi), 1 / (lo * hi), vrlis::Sqr(50 * 20 / lo)}) {
    INFO("price " << price);
    vrlis::EffortSettings undecided{true, price};
    undecided.decide = false;
    for (const char* name : {"novak", "auto"}) {
      INFO(name);
      const auto method = *vrlis::ParseGatherSamplers(name);
      const auto off = Samples(s, method, {});
      REQUIRE(!off.empty());
      CHECK(Samples(s, method, undecided) == off);
      CHECK(Samples(s, method, vrlis::EffortSettings{true, price}) != off);
    }
    for (auto [model, name] : {std::pair{vrlis::EffortModel::Cheapest, "equiangular"},
                               std::pair{vrlis::EffortModel::Mixture, "cauchy-mixture"},
                               std::pair{vrlis::EffortModel::Accurate, "full-product+marginal"}}) {
      INFO(name);
      undecided.model = model;
      CHECK(Samples(s, automatic, undecided) == Samples(s, *vrlis::ParseGatherSamplers(name), {}));
    }
  }
}

// `auto` under a price: gathers asking for more than `accurate` ceilings take the most
// accurate model, sample for sample; those below, at the floor too, auto's own rule (neither
// that nor the cheapest model) unless the call asks for the cheapest (EffortSettings::model);
// the mixture of models stays unbiased (a sabotaged 1 / q fails).
TEST_CASE("auto with the effort control takes the model its demand pays for", "[gather][effort]") {
  Setup s = MakeSetup();
  const auto automatic = *vrlis::ParseGatherSamplers("auto");
  auto [lo, hi] = BoundRange(s);
  vrlis::EffortSettings cheap{true, vrlis::Sqr(0.04 / hi)};  // every demand below the floor
  REQUIRE(!Samples(s, automatic, cheap).empty());
  CHECK(Samples(s, automatic, cheap) != Samples(s, *vrlis::ParseGatherSamplers("equiangular"), cheap));
  CHECK(Samples(s, automatic, cheap) != Samples(s, *vrlis::ParseGatherSamplers("full-product+marginal"), cheap));
  vrlis::EffortSettings middle{true, vrlis::Sqr(2 / hi)};  // every demand below 2 samples
  CHECK(Samples(s, automatic, middle) != Samples(s, *vrlis::ParseGatherSamplers("full-product+marginal"), middle));
  CHECK(Samples(s, automatic, middle) != Samples(s, *vrlis::ParseGatherSamplers("equiangular"), middle));
  vrlis::EffortSettings accurate{true, vrlis::Sqr(50 * 20 / lo)};  // every demand above 2.3 ceilings
  CHECK(Samples(s, automatic, accurate) == Samples(s, *vrlis::ParseGatherSamplers("full-product+marginal"), accurate));
  // A call that asks for the cheapest model, the mixture or the accurate one takes it below
  // the accurate tier, priced or not, and the accurate model above it.
  for (auto [model, name] : {std::pair{vrlis::EffortModel::Cheapest, "equiangular"},
                             std::pair{vrlis::EffortModel::Mixture, "cauchy-mixture"},
                             std::pair{vrlis::EffortModel::Accurate, "full-product+marginal"}})
    for (vrlis::EffortSettings e : {vrlis::EffortSettings{true}, middle, accurate}) {
      e.model = model;
      const char* expected = e.price == accurate.price ? "full-product+marginal" : name;
      INFO("price " << e.price << ", " << name);
      CHECK(Samples(s, automatic, e) == Samples(s, *vrlis::ParseGatherSamplers(expected), e));
    }
  // Demands spread over both models: 1.0 at the geometric middle of the predictions.
  s.method = automatic;
  vrlis::EffortSettings mixed{true, 1 / (lo * hi)};
  const Moments off = Estimate(s, {}, 20000), on = Estimate(s, mixed, 20000);
  INFO("off " << off.mean << " +- " << off.se << ", on " << on.mean << " +- " << on.se);
  CHECK(Z(on, off) < 4);
  CHECK(Z(Estimate(s, mixed, 20000, true), off) > 4);
}

// The segment sampler a model stands for (SegmentSamplerFor): auto's model in place of its
// rule, every other sampler its own whatever the model (the renderer's VPL gathers use it).
TEST_CASE("an effort model replaces auto's rule and no other sampler", "[gather][effort]") {
  using vrlis::EffortModel;
  auto named = [](const char* name) { return *vrlis::ParseSegmentSampler(name); };
  CHECK(vrlis::SegmentSamplerFor(named("auto"), EffortModel::Chosen) == named("auto"));
  CHECK(vrlis::SegmentSamplerFor(named("auto"), EffortModel::Cheapest) == named("equiangular"));
  CHECK(vrlis::SegmentSamplerFor(named("auto"), EffortModel::Mixture) == named("cauchy-mixture"));
  CHECK(vrlis::SegmentSamplerFor(named("auto"), EffortModel::Accurate) == named("full-product"));
  for (const char* name : {"equiangular", "novak", "cauchy-sum", "cauchy-mixture", "full-product"})
    for (EffortModel m : {EffortModel::Chosen, EffortModel::Accurate, EffortModel::Cheapest, EffortModel::Mixture}) {
      INFO(name << ", model " << static_cast<int>(m));
      CHECK(vrlis::SegmentSamplerFor(named(name), m) == named(name));
    }
}

// GatherSample::over_equiangular and over_mixture: over auto's samples, weight^2 x the ratio
// estimates equiangular sampling's and the mixture's second moments (the same step one),
// within 4 standard errors, on queries where auto's rule takes a fit (a dense medium, a
// peaked lobe); weight^2 alone (the sabotage) estimates auto's own, which is rejected. Other
// samplers leave both 0, and auto leaves over_mixture 0 unless the call measures it.
TEST_CASE("auto's samples estimate equiangular sampling's and the mixture's second moments", "[gather][effort]") {
  Setup s = MakeSetup();
  s.medium = vrlis::Medium<Real>::FromScatteringExtinction(Real(0.8), Real(1.5), Real(2));  // long optical depths, a peaked lobe
  vrlis::EffortSettings measure;
  measure.measure_mixture = true;
  using Ratio = Real vrlis::GatherSample<Real>::*;
  auto second_moments = [&](const char* method, Ratio over) {
    std::vector<vrlis::RunningMoments> m(s.vrls.size());
    std::mt19937 rng(9);
    std::uniform_real_distribution<Real> u(0, 1);
    for (int call = 0; call < 20000; ++call)
      Gather(*vrlis::ParseGatherSamplers(method), s, measure, s.weights.data(), int(s.vrls.size()), [&] { return u(rng); },
             [&](int i, const vrlis::GatherSample<Real>& g, Real) {
               m[std::size_t(i)].add(double(g.weight) * g.weight * (over ? g.*over : 1));
             });
    return m;
  };
  const auto sabotaged = second_moments("auto", nullptr);
  for (auto [name, over] : {std::pair{"equiangular", &vrlis::GatherSample<Real>::over_equiangular},
                            std::pair{"cauchy-mixture", &vrlis::GatherSample<Real>::over_mixture}}) {
    const auto exact = second_moments(name, nullptr), estimated = second_moments("auto", over);
    int rejected = 0;
    for (std::size_t i = 0; i < s.vrls.size(); ++i) {
      auto z = [&](const vrlis::RunningMoments& m) {
        return std::abs(m.mean() - exact[i].mean()) / std::hypot(m.standard_error(), exact[i].standard_error());
      };
      INFO(name << ", VRL " << i << ": its own " << exact[i].mean() << ", estimated " << estimated[i].mean()
                << ", auto's own " << sabotaged[i].mean());
      CHECK(z(estimated[i]) < 4);
      rejected += z(sabotaged[i]) > 4;
    }
    CHECK(rejected >= int(s.vrls.size()) / 2);
  }
  // Whether any of a method's samples carries each ratio: {over_equiangular, over_mixture}.
  auto carried = [&](const char* method, const vrlis::EffortSettings& e) {
    std::pair<bool, bool> any{false, false};
    Gather(*vrlis::ParseGatherSamplers(method), s, e, s.weights.data(), int(s.vrls.size()), [] { return Real(0.5); },
           [&](int, const vrlis::GatherSample<Real>& g, Real) {
             any.first |= g.over_equiangular != 0;
             any.second |= g.over_mixture != 0;
           });
    return any;
  };
  CHECK(carried("novak", measure) == std::pair{false, false});
  CHECK(carried("auto", {}) == std::pair{true, false});
}

// MediumGatherBounds and SurfaceGatherBounds (vector lanes) against the quick and tight bounds
// one VRL at a time, in float, on random configurations with near-parallel lines, VRLs that pass
// next to the camera line, unbounded camera segments and partial batches: the same bounds but
// for rounding (the lanes' square roots by Newton steps). A sabotaged lane (the bound of the
// next VRL) is caught by the same comparison.
TEST_CASE("batched bounds in vector lanes agree with the bounds one at a time", "[gather][effort]") {
  // On both lane paths (core/dispatch.hpp), the same configurations: the control counts the
  // bounds at the cost of the path in use, and its decisions must not depend on the path.
  std::vector<float> path_values[2];
  for (const bool widest : {true, false}) {
    vrlis::UseWidestLanes(widest);
    std::vector<float>& values = path_values[widest];
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(0, 1);
    auto direction = [&] {
      float z = 2 * u(rng) - 1, phi = 2 * vrlis::kPi<float> * u(rng), r = std::sqrt(1 - z * z);
      return vrlis::Vec3<float>{r * std::cos(phi), r * std::sin(phi), z};
    };
    double worst_quick = 0, worst_tight = 0, sabotaged = 0;
    for (int c = 0; c < 400; ++c) {
      const float g = 1.8f * u(rng) - 0.9f, sigma_s = 0.1f + u(rng), sigma_t = sigma_s + u(rng);
      const auto medium = vrlis::Medium<float>::FromScatteringExtinction(g, sigma_s, sigma_t);
      const vrlis::Vec3<float> camera_dir = direction();
      const float tmax = c % 5 == 0 ? std::numeric_limits<float>::infinity() : 0.5f + 4 * u(rng);
      const vrlis::RaySegment<float> camera{{0, 0, 0}, camera_dir, 0.2f * u(rng), tmax};
      const int count = 1 + c % vrlis::kBoundBatch;
      std::vector<vrlis::VrlSegment<float>> vrls;
      for (int i = 0; i < count; ++i) {
        vrlis::Vec3<float> dir = direction(), origin{4 * u(rng) - 2, 4 * u(rng) - 2, 4 * u(rng) - 2};
        if (i % 3 == 1) dir = vrlis::Normalize(camera_dir + 1e-3f * direction());  // near-parallel
        if (i % 4 == 2) origin = (1 + u(rng)) * camera_dir + 1e-3f * direction();  // next to the camera line
        vrls.push_back({origin, dir, 0.3f + 3 * u(rng)});
      }
      // A surface point on the camera segment, facing it (half the VRLs behind it, some partly).
      const vrlis::Vec3<float> point = camera.at(camera.tmin + 0.5f), normal = direction();
      float quick[2][vrlis::kBoundBatch], tight[2][vrlis::kBoundBatch];
      vrlis::MediumGatherBounds(camera, vrls.data(), count, medium, quick[0], tight[0]);
      vrlis::SurfaceGatherBounds(point, normal, vrls.data(), count, medium, quick[1], tight[1]);
      for (int kind = 0; kind < 2; ++kind) values.insert(values.end(), quick[kind], quick[kind] + count),
                                           values.insert(values.end(), tight[kind], tight[kind] + count);
      for (int i = 0; i < count; ++i) {
        const vrlis::VrlSegment<float>& vrl = vrls[std::size_t(i)];
        const double q[2] = {vrlis::MediumGatherQuickBound(camera, vrl, medium),
                             vrlis::SurfaceGatherQuickBound(point, normal, vrl, medium)};
        const double t[2] = {vrlis::MediumGatherBound(camera, vrl, medium),
                             vrlis::SurfaceGatherBound(point, normal, vrl, medium)};
        for (int kind = 0; kind < 2; ++kind) {
          INFO("configuration " << c << ", VRL " << i << ", kind " << kind << ": quick " << quick[kind][i] << " vs "
                                << q[kind] << ", tight " << tight[kind][i] << " vs " << t[kind]);
          REQUIRE(std::isfinite(quick[kind][i]));
          REQUIRE(std::isfinite(tight[kind][i]));
          REQUIRE((quick[kind][i] == 0) == (q[kind] == 0));  // behind the surface in both or neither
          REQUIRE((tight[kind][i] == 0) == (t[kind] == 0));
          if (t[kind] == 0) continue;
          worst_quick = std::max(worst_quick, std::abs(quick[kind][i] / q[kind] - 1));
          worst_tight = std::max(worst_tight, std::abs(tight[kind][i] / t[kind] - 1));
          if (count > 1 && tight[kind][(i + 1) % count] > 0)
            sabotaged = std::max(sabotaged, std::abs(tight[kind][(i + 1) % count] / t[kind] - 1));
        }
      }
    }
    INFO("largest relative difference: quick " << worst_quick << ", tight " << worst_tight << "; sabotaged "
                                                << sabotaged);
    CHECK(worst_quick < 1e-5);  // measured 8.1e-7
    CHECK(worst_tight < 2e-4);  // measured 2.8e-5 (the cosines next to the camera line are ill-conditioned)
    CHECK(sabotaged > 1e-2);
  }
  vrlis::UseWidestLanes(true);
  CHECK(path_values[0] == path_values[1]);  // no multiply-adds: the same rounding on either path
}

TEST_CASE("VrlMarginal fits the gathers whose score reaches the threshold, the others take VrlPoint's density",
          "[gather][effort]") {
  Setup s = MakeSetup();
  s.method = *vrlis::ParseGatherSamplers("full-product+marginal");
  const int n = int(s.vrls.size());
  std::vector<double> score(std::size_t(n), 0.0);
  std::vector<Real> bound(std::size_t(n), 0);
  vrlis::MarginalFitScores(s.camera, s.medium, s.vrls.data(), s.weights.data(), n, bound.data(), score.data());
  std::vector<double> sorted = score;
  std::sort(sorted.begin(), sorted.end());
  vrlis::EffortSettings effort;
  effort.marginal_threshold = sorted[std::size_t(n / 2)];  // half the VRLs fitted
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> u(0, 1);
  int fitted = 0, pointed = 0, distinct = 0;
  for (int run = 0; run < 40; ++run)
    Gather(s.method, s, effort, s.weights.data(), n,
           [&] { return u(rng); },
           [&](int i, const vrlis::GatherSample<Real>& g, Real) {
             if (!(g.pdf_v > 0)) return;
             const vrlis::MediumGatherQuery<Real> q{s.camera, s.vrls[std::size_t(i)], s.medium};
             const double marginal = vrlis::VrlMarginal<Real>(q).pdf(g.v);
             const double point = vrlis::VrlPoint<Real>(q).pdf(g.v);
             const bool fit = score[std::size_t(i)] >= effort.marginal_threshold;
             INFO("VRL " << i << (fit ? " fitted" : " not fitted") << ", v " << g.v);
             REQUIRE(g.pdf_v == Approx(fit ? marginal : point).epsilon(2e-3));
             ++(fit ? fitted : pointed);
             distinct += std::abs(marginal / point - 1) > 0.05;  // the two can be told apart
           });
  CHECK(fitted > 100);
  CHECK(pointed > 100);
  CHECK(distinct > 100);
}

TEST_CASE("ScoreOctaves: the threshold fits at most the share asked for, one octave lower more", "[gather][effort]") {
  vrlis::ScoreOctaves octaves;
  CHECK(std::isinf(octaves.Threshold(0.2)));  // nothing learned: no gather fitted by it
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> exponent(-40, 40);
  std::vector<double> scores;
  for (int i = 0; i < 20000; ++i) {
    scores.push_back(std::exp2(exponent(rng)));
    octaves.Add(scores.back());
  }
  octaves.Add(0);
  octaves.Add(std::numeric_limits<double>::quiet_NaN());
  REQUIRE(octaves.total() == scores.size());  // zeros and NaN uncounted
  auto share_from = [&](double threshold) {
    return double(std::count_if(scores.begin(), scores.end(), [&](double x) { return x >= threshold; })) /
           double(scores.size());
  };
  for (double fraction : {0.01, 0.05, 0.2, 0.5, 0.9}) {
    const double threshold = octaves.Threshold(fraction);
    INFO("fraction " << fraction << ", threshold " << threshold);
    CHECK(share_from(threshold) <= fraction);
    CHECK(share_from(threshold / 2) > fraction);
  }
}

// "null: all equal": a null weights pointer compiles (Real comes from the segments) and takes
// every VRL's weight as 1, the control on and deciding; weights of 3 change the decisions
// (the comparison can fail).
TEST_CASE("a null weights pointer gathers as weights of one", "[gather][effort]") {
  const Setup s = MakeSetup();
  vrlis::EffortSettings effort;
  effort.on = true;
  effort.price = 1e6;
  auto samples = [&](const Real* weights) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<Real> u(0, 1);
    std::vector<double> taken;
    for (int r = 0; r < 50; ++r)
      Gather(s.method, s, effort, weights, int(s.vrls.size()),
             [&] { return u(rng); },
             [&](int i, const vrlis::GatherSample<Real>& g, Real w) { taken.push_back(i + g.weight * w); });
    return taken;
  };
  std::vector<Real> ones(s.vrls.size(), Real(1));
  const std::vector<double> with_ones = samples(ones.data());
  REQUIRE(with_ones.size() > 100);
  CHECK(samples(nullptr) == with_ones);
  std::fill(ones.begin(), ones.end(), Real(3));
  CHECK(samples(ones.data()) != with_ones);
}
