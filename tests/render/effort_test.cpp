// The effort control in the renderer (vrlis/effort/policy.hpp, vrlis/effort/price.hpp):
// - a pass's decisions are a function of the price learned from the passes before it (with
//   the scene's sampler and with auto): pass 3 rendered by a fresh renderer given that price
//   equals the original's pass 3 bit for bit,
//   at one thread and at four (a price updated within the pass, from the pass's own pixels,
//   would depend on their order), and differs without it (the control acted);
// - decisions follow the price: in room, where direct lighting holds almost all the variance
//   (docs/compare/decomposition.md), the gathers fall to the floor (by pass 5 under three times
//   its share of the uncontrolled count); in the bidirectional scene, which is nothing but gathers, the
//   gathers taken stay at or above one per VRL;
// - a call of gathers is taken at the floor's rate where its gathers carry no variance (room)
//   and mostly taken where they carry it all (bidirectional);
// - roulette raises the samples' weights and the floor bounds them: in room the largest effort
//   weight exceeds 1 and is at most 1 / floor, every weight finite; recording them changes no image;
// - a split remainder (SplitRemainder) keeps a path's mean at rates 0.4, 1 and 2.6 and its
//   statistics estimate the path's second moment; without its 1 / rate it is rejected;
// - the remainder's demand follows the price: above 2 paths per camera vertex in corner, whose
//   remainder holds most of the variance, and under a quarter of that in room, whose holds almost none;
// - split VPL connections (SplitConnections) keep their gather's mean at rates 2, 2.6 and 13.3
//   and their statistics estimate one connection's variance within it; without the 1 / rate
//   it is rejected; their demand follows the price: above 8 at the cube's surfaces, whose VPLs
//   hold most of its variance, and under an eighth of that in room's;
// - `auto` takes a model cheaper than its rule where the variance it adds is worth less than
//   the time it saves: in room (gathers without variance) equiangular or the mixture, and not
//   equiangular in the bidirectional scene at g = 0.9;
// - with the control off, `auto` still takes the image's model by the price (room: the cheapest,
//   whose pass is equiangular sampling's but in the pixels that explore the rule) and nothing
//   else: no gather decided, no split count asked, every weight 1 (the same price with the
//   control on decides), a pass a function of that price;
// - `auto` takes the accurate model where its variance is worth its time: in the
//   bidirectional scene at g = 0, not in room; on synthetic passes where the first pass's pairs
//   show it worth its time, within a margin, and then for good; a pair changes no gather and its
//   pixel delta is what the accurate model on the same random numbers adds instead; the pilot
//   pairs no pixel where its probe shows that even a free accurate model could not pay (room,
//   and a synthetic probe either side of the bound), and pairs where it could (bidirectional);
// - the price compares the image's states whole: on synthetic passes it takes the mixture
//   where its added variance and saved time lower V x T (also where first order says the
//   rule) and the rule where they raise it;
// - the gathers are decided one by one where that pays and taken once where it does not: in
//   room (decisions skip almost every gather), not in the bidirectional scene at g = 0 with
//   equiangular sampling (bounds that cost more than the gathers, for little variance);
// - the controlled image's mean is the uncontrolled one's: per 8 x 8 block of the
//   bidirectional scene (where roulette and splitting act most), of room (where whole calls
//   are rouletted) and of the cube (where the remainder is split), z-scores within a
//   Bonferroni bound, and a control x1.1 rejected.
#include <tbb/global_control.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>

#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include <vrlis/core/running_moments.hpp>
#include <vrlis_integration/camera_paths.hpp>
#include <vrlis_integration/gather.hpp>
#include <vrlis_integration/light_paths.hpp>
#include <vrlis_integration/weight_log.hpp>
#include <vrlis_scenes/scenes.hpp>

#include "block_stats.hpp"
#include "uncontrolled.hpp"

namespace {

vrlis::integration::RenderSettings Settings(const vrlis::scenes::BuiltScene& built, int size, bool effort) {
  vrlis::integration::RenderSettings s;
  s.width = s.height = size;
  s.vrls_per_pass = 32;
  s.transport = vrlis::test::Uncontrolled(built.transport);
  s.transport.effort.on = effort;
  return s;
}

// A scene for the tests of where effort goes. The bidirectional light's lattice is held fixed:
// rotated per pass, most of that scene's noise is which directions the beams take, which no
// number of gathers per VRL reduces; fixed, all of it is the gathers'.
std::optional<vrlis::scenes::BuiltScene> EffortScene(const char* name) {
  auto built = vrlis::scenes::BuildScene(name, {});
  if (built)
    for (vrlis::integration::PointLight& l : built->scene.lights.points) l.rotate_lattice = false;
  return built;
}

// The mean over a 16 x 16 render's pixels of f(price, settings, x, y), the price learned from
// five passes with the control on.
template <typename F>
double MeanOverPixels(const char* scene, F&& f) {
  auto built = EffortScene(scene);
  REQUIRE(built);
  const vrlis::integration::RenderSettings s = Settings(*built, 16, true);
  vrlis::integration::VrlRenderer r(built->scene, s);
  for (std::uint64_t pass = 0; pass < 5; ++pass) r.RenderPass(1, pass, nullptr);
  double sum = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) sum += f(r.effort_price(), s, x, y);
  return sum / (s.width * s.height);
}

// A split kind's demand after 5 passes, over the pixels (MeanOverPixels).
double MeanSplitDemand(const char* scene, vrlis::SplitKind kind) {
  return MeanOverPixels(scene, [kind](const vrlis::EffortPrice& price, const vrlis::integration::RenderSettings&, int x,
                                      int y) { return price.split_demand(kind, x, y); });
}

bool Same(const vrlis::integration::Film& a, const vrlis::integration::Film& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(vrlis::integration::Spectrum)) == 0;
}

// Pass 3 of a fresh renderer given `learned` (the price after passes 0-2) is `original` bit for
// bit, at one thread and at four: a pass's decisions are the price's, not its pixels' order.
void CheckPassFromPrice(const vrlis::scenes::BuiltScene& built, const vrlis::integration::RenderSettings& s,
                        const vrlis::EffortPrice& learned, const vrlis::integration::Film& original) {
  for (int threads : {1, 4}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
    vrlis::integration::VrlRenderer b(built.scene, s);
    b.set_effort_price(learned);
    INFO(threads << " threads");
    CHECK(Same(b.RenderPass(1, 3, nullptr), original));
  }
}

}  // namespace

TEST_CASE("a pass's effort decisions come from the passes before it", "[render][effort]") {
  // The scene's own sampler, and `auto`, whose model choice is learned too (EffortPrice::model).
  const bool automatic = GENERATE(false, true);
  INFO("auto " << automatic);
  auto built = vrlis::scenes::BuildScene("room", {});
  REQUIRE(built);
  vrlis::integration::RenderSettings s = Settings(*built, 16, true);
  if (automatic) s.transport.sampling = *vrlis::ParseGatherSamplers("auto");
  vrlis::integration::VrlRenderer a(built->scene, s);
  for (std::uint64_t pass = 0; pass < 3; ++pass) a.RenderPass(1, pass, nullptr);
  const vrlis::EffortPrice learned = a.effort_price();
  REQUIRE(learned.passes() == 4);  // the pilot's and three
  REQUIRE(learned.price(vrlis::GatherKind::Medium) > 0);
  REQUIRE(learned.price(vrlis::GatherKind::Surface) > 0);
  const vrlis::integration::Film original = a.RenderPass(1, 3, nullptr);
  CheckPassFromPrice(*built, s, learned, original);
  vrlis::integration::VrlRenderer fresh(built->scene, s);
  CHECK_FALSE(Same(fresh.RenderPass(1, 3, nullptr), original));
}

TEST_CASE("effort: gathers without variance fall to the floor, a scene of gathers keeps them", "[render][effort]") {
  auto gathers = [](const char* scene, int pass) {
    auto built = EffortScene(scene);
    REQUIRE(built);
    vrlis::integration::VrlRenderer r(built->scene, Settings(*built, 16, true)),
        once(built->scene, Settings(*built, 16, false));  // takes every gather once
    vrlis::integration::PassStats first, stats;
    once.RenderPass(1, 0, &first);
    for (int p = 0; p <= pass; ++p) r.RenderPass(1, std::uint64_t(p), &stats);
    return double(stats.gathers) / double(first.gathers);
  };
  const double room = gathers("room", 5), bidirectional = gathers("bidirectional", 5);
  INFO("gathers in pass 5 over an uncontrolled pass: room " << room << ", bidirectional " << bidirectional);
  CHECK(room < 3 * vrlis::EffortSettings{}.floor);
  CHECK(bidirectional >= 1);
}

TEST_CASE("effort: calls whose gathers carry no variance are taken at the floor's rate", "[render][effort]") {
  auto mean_rate = [](const char* scene) {
    return MeanOverPixels(scene, [](const vrlis::EffortPrice& price,
                                    const vrlis::integration::RenderSettings& s, int x, int y) {
      vrlis::EffortSettings e = s.transport.effort;
      e.price = price.price(vrlis::GatherKind::Medium);
      e.call_demand = price.call_demand(vrlis::GatherKind::Medium, x, y);
      return vrlis::EffortCallRate(e);
    });
  };
  const double room = mean_rate("room"), bidirectional = mean_rate("bidirectional");
  INFO("mean rate of a medium-to-medium call after 5 passes: room " << room << ", bidirectional " << bidirectional);
  CHECK(room < 1.5 * vrlis::EffortSettings{}.floor);
  CHECK(bidirectional > 0.5);
}

TEST_CASE("effort: roulette's largest weight is above one and at most 1 / floor", "[render][effort]") {
  auto built = vrlis::scenes::BuildScene("room", {});
  REQUIRE(built);
  vrlis::integration::WeightLog log;
  vrlis::integration::RenderSettings s = Settings(*built, 16, true);
  s.transport.weight_log = &log;
  vrlis::integration::VrlRenderer r(built->scene, s);
  for (std::uint64_t pass = 0; pass < 5; ++pass) r.RenderPass(1, pass, nullptr);
  const float largest = log.largest_effort_weight();
  INFO(log.samples() << " samples, largest effort weight " << largest << ", " << log.non_finite() << " not finite");
  CHECK(log.non_finite() == 0);
  CHECK(largest > 1);
  CHECK(largest <= static_cast<float>(1 / s.transport.effort.floor));
  // With the control off (a pass of (seed, pass) alone) recording changes nothing.
  s.transport.effort.on = false;
  const vrlis::integration::Film logged = vrlis::integration::VrlRenderer(built->scene, s).RenderPass(1, 0, nullptr);
  s.transport.weight_log = nullptr;
  CHECK(Same(logged, vrlis::integration::VrlRenderer(built->scene, s).RenderPass(1, 0, nullptr)));
}

TEST_CASE("effort keeps the image's mean", "[render][effort]") {
  const char* scene = GENERATE("bidirectional", "room", "cube");
  INFO(scene);
  auto built = EffortScene(scene);
  REQUIRE(built);
  const int size = 16, block = 8, passes = 400;
  vrlis::integration::VrlRenderer off(built->scene, Settings(*built, size, false)), on(built->scene, Settings(*built, size, true));
  vrlis::test::BlockEstimate a = vrlis::test::EstimateBlocks(off, size, size, block, passes, 1);
  vrlis::test::BlockEstimate b = vrlis::test::EstimateBlocks(on, size, size, block, passes, 2);
  const vrlis::test::ZSummary z = vrlis::test::Compare(a, b);
  for (double& m : b.mean) m *= 1.1;  // a control the budget must resolve
  for (double& e : b.stderr_) e *= 1.1;
  const vrlis::test::ZSummary zc = vrlis::test::Compare(a, b);
  INFO(z.Describe() << "; control x1.1: " << zc.Describe());
  CHECK(z.Pass());
  CHECK(z.n == 4);
  CHECK_FALSE(zc.Pass());
}

TEST_CASE("effort: a split remainder keeps its mean and learns its second moment", "[render][effort]") {
  // A "path" worth u, uniform in [0, 1): mean 1/2, second moment 1/3. At rates below, at and
  // above one the split sum keeps the mean and SplitRecord's m2 per launch estimates 1/3;
  // the sabotage (the split sum without its 1 / rate) must be rejected.
  const double rate = GENERATE(0.4, 1.0, 2.6);
  INFO("rate " << rate);
  vrlis::integration::Rng rng(7, 0, 0, vrlis::integration::StreamPurpose::Camera);
  vrlis::SplitRecord stats;
  vrlis::RunningMoments kept, sabotaged;
  for (int k = 0; k < 40000; ++k) {
    const float y = vrlis::integration::SplitRemainder(rate, rng, &stats, [&] {
      return vrlis::integration::Spectrum(rng.Uniform());
    }).Average();
    kept.add(y);
    sabotaged.add(y * rate);
  }
  auto z = [](const vrlis::RunningMoments& m, double mean) { return (m.mean() - mean) / m.standard_error(); };
  INFO("z " << z(kept, 0.5) << ", sabotaged z " << z(sabotaged, 0.5) << ", m2 per launch "
            << stats.m2 / stats.launches << ", paths per launch " << stats.samples / stats.launches);
  CHECK(std::abs(z(kept, 0.5)) < 4);
  CHECK(std::abs(stats.m2 / stats.launches - 1.0 / 3) < 0.015);
  CHECK(std::abs(stats.samples / stats.launches - rate) < 0.02);
  if (rate != 1) CHECK(std::abs(z(sabotaged, 0.5)) > 4);
}

TEST_CASE("effort: split VPL connections keep their gather's mean and learn its within variance", "[render][effort]") {
  // A "connection" worth 2 u, u uniform in [0, 1), scaled by 1/2 and seen through a path of
  // throughput 3: a gather's mean 1/2 whatever the rate, a connection's pixel contribution 3 u
  // of variance 9/12 within the gather. SplitRecord's m2 per launch estimates it; the sabotage
  // (the gather weighted 1 / floor(rate), the count it mostly takes, not 1 / rate) must be rejected.
  const double rate = GENERATE(2.0, 2.6, 13.3);
  INFO("rate " << rate);
  vrlis::integration::Rng rng(9, 0, 0, vrlis::integration::StreamPurpose::Camera);
  vrlis::SplitRecord stats;
  const vrlis::integration::VplConnections connections{rate, vrlis::integration::Spectrum(3.f), &stats};
  vrlis::RunningMoments kept, sabotaged;
  for (int k = 0; k < 40000; ++k) {
    const float y = vrlis::integration::SplitConnections(connections, vrlis::integration::Spectrum(0.5f), rng, [&] {
      return vrlis::integration::Spectrum(2 * rng.Uniform());
    }).Average();
    kept.add(y);
    sabotaged.add(y * rate / std::floor(rate));
  }
  auto z = [](const vrlis::RunningMoments& m, double mean) { return (m.mean() - mean) / m.standard_error(); };
  INFO("z " << z(kept, 0.5) << ", sabotaged z " << z(sabotaged, 0.5) << ", m2 per launch "
            << stats.m2 / stats.launches << ", connections per launch " << stats.samples / stats.launches);
  CHECK(std::abs(z(kept, 0.5)) < 4);
  CHECK(std::abs(stats.m2 / stats.launches - 0.75) < 0.015);
  CHECK(std::abs(stats.samples / stats.launches - rate) < 0.02);
  if (rate != std::floor(rate)) CHECK(std::abs(z(sabotaged, 0.5)) > 4);
}

TEST_CASE("effort: VPL connections follow the price where they hold the noise", "[render][effort]") {
  using vrlis::SplitKind;
  const double cube = MeanSplitDemand("cube", SplitKind::VplSurface), room = MeanSplitDemand("room", SplitKind::VplSurface);
  INFO("mean surface-to-surface VPL demand after 5 passes: cube " << cube << ", room " << room);
  CHECK(cube > 8);          // its VPLs hold most of the variance (docs/compare/decomposition.md)
  CHECK(room < cube / 8);   // direct light holds almost all of room's
}

TEST_CASE("effort: the remainder is split where its paths hold the noise, never rouletted", "[render][effort]") {
  using vrlis::SplitKind;
  const double corner = MeanSplitDemand("corner", SplitKind::Remainder), room = MeanSplitDemand("room", SplitKind::Remainder);
  INFO("mean remainder demand after 5 passes: corner " << corner << ", room " << room);
  CHECK(corner > 2);           // its remainder holds most of the variance at a few percent of the time
  CHECK(room < corner / 4);    // its remainder holds almost none
}

TEST_CASE("effort: auto weighs the models by the variance each adds or removes", "[render][effort]") {
  // What the first price weighs the image's model by, from the pilot: its variances are
  // the image's and the samples', which the seed fixes, and are checked here; its work is
  // counted, and the choice it makes with them is the synthetic test's (below).
  using Weighing = vrlis::EffortPrice::ModelWeighing;
  auto weigh = [](const char* scene, float g, int size, bool fixed_lattice) {
    vrlis::scenes::MediumOverrides medium;
    medium.g = g;
    auto built = vrlis::scenes::BuildScene(scene, medium);
    REQUIRE(built);
    if (fixed_lattice)  // as EffortScene: all of the noise the gathers'
      for (vrlis::integration::PointLight& l : built->scene.lights.points) l.rotate_lattice = false;
    vrlis::integration::RenderSettings s = Settings(*built, size, true);
    s.transport.sampling = *vrlis::ParseGatherSamplers("auto");
    vrlis::integration::VrlRenderer r(built->scene, s);
    r.RenderPass(1, 0, nullptr);
    return std::pair{r.effort_price().first_weighing(vrlis::GatherKind::Medium), r.effort_price().pairs_pay()};
  };
  // The image's measured variance: the rule's and the pilots' shares of theirs.
  auto measured = [](const Weighing& w) {
    return w.v_rule + w.cheapest.share * w.cheapest.dv + w.mixture.share * w.mixture.dv;
  };
  auto describe = [&](const Weighing& w) {
    std::ostringstream o;
    o << "measured " << measured(w) << ", v_rule " << w.v_rule << ", dv: cheapest " << w.cheapest.dv << " mixture " << w.mixture.dv << " accurate "
      << w.accurate.dv;
    return o.str();
  };
  auto known = [](const Weighing& w) { return w.cheapest.known && w.mixture.known && w.accurate.known; };
  // Room's gathers hold almost none of the variance: no model changes it by much, and the
  // pilot's probe shows that the accurate model cannot pay, so that no pixel pairs.
  const auto [room, room_pairs] = weigh("room", 0.5f, 16, false);
  INFO("room: " << describe(room));
  REQUIRE((room.cheapest.known && room.mixture.known));
  CHECK(std::abs(room.cheapest.dv) < 0.01 * room.v_rule);
  CHECK(std::abs(room.mixture.dv) < 0.01 * room.v_rule);
  CHECK_FALSE(room_pairs);
  CHECK_FALSE(room.accurate.known);
  // Bidirectional, g = 0.9: equiangular sampling has many times a fit's variance.
  const auto [forward, forward_pairs] = weigh("bidirectional", 0.9f, 16, false);
  INFO("bidirectional, g = 0.9: " << describe(forward));
  CHECK(forward_pairs);
  REQUIRE(known(forward));
  CHECK(forward.cheapest.dv > measured(forward));
  // Bidirectional, g = 0, at the study's size (the pilot's pixels are the estimate's) and
  // with the light's lattice fixed (its rotation adds noise that no model removes): the
  // accurate model removes most of the variance.
  const auto [plain, plain_pairs] = weigh("bidirectional", 0.f, 48, true);
  INFO("bidirectional, g = 0: " << describe(plain));
  CHECK(plain_pairs);
  REQUIRE(known(plain));
  CHECK(plain.accurate.dv < -0.6 * plain.v_rule);
  CHECK(plain.accurate.dv > -plain.v_rule);  // a variance cannot fall below 0
}

TEST_CASE("effort off: auto still takes the image's model by the price, and every gather once",
          "[render][effort]") {
  // With the control off `auto` learns the image's model from the passes before (room's gathers
  // hold almost none of the variance: the cheapest model, as with the control on)
  // and nothing else: no gather decided, no split kind given a count, every effort weight 1.
  auto built = vrlis::scenes::BuildScene("room", {});
  REQUIRE(built);
  vrlis::integration::WeightLog log;
  vrlis::integration::RenderSettings s = Settings(*built, 16, false);
  s.transport.sampling = *vrlis::ParseGatherSamplers("auto");
  s.transport.weight_log = &log;
  vrlis::integration::VrlRenderer r(built->scene, s);
  for (std::uint64_t pass = 0; pass < 3; ++pass) r.RenderPass(1, pass, nullptr);
  const vrlis::EffortPrice learned = r.effort_price();
  const vrlis::EffortModel medium = learned.model(vrlis::GatherKind::Medium);
  INFO("medium-to-medium model " << int(medium) << "; " << log.samples() << " samples, largest effort weight "
                                 << log.largest_effort_weight());
  REQUIRE(learned.passes() == 4);  // the pilot's and three
  CHECK(medium == vrlis::EffortModel::Cheapest);
  CHECK(learned.model(vrlis::GatherKind::Surface) == vrlis::EffortModel::Cheapest);
  CHECK(log.samples() > 0);
  CHECK(log.largest_effort_weight() == 1.f);
  // The price's settings for every pixel, on the numbers that decide most (u = 0: the trial's
  // share would decide), and the same price with the control on, which must decide (a sabotage).
  auto settings = [&](bool on) {
    vrlis::EffortPrice price = learned;
    vrlis::EffortSettings base = s.transport.effort;
    base.on = true, base.decide = on;
    price.BeginPass(base);
    int decided = 0, counts = 0;
    for (int y = 0; y < s.height; ++y)
      for (int x = 0; x < s.width; ++x) {
        const vrlis::PixelEffort p = price.Pixel(x, y, [] { return 0.0; });
        decided += p.medium.decide + p.surface.decide;
        for (double rate : p.split_rates) counts += !std::isnan(rate);
      }
    return std::pair{decided, counts};
  };
  const auto [decided, counts] = settings(false);
  const auto [decided_on, counts_on] = settings(true);
  INFO("gathers decided " << decided << " (the control on: " << decided_on << "), split counts asked " << counts
                          << " (" << counts_on << ")");
  CHECK(decided == 0);
  CHECK(counts == 0);
  CHECK(decided_on > 0);
  CHECK(counts_on > 0);
  // A pass is a function of the price learned from the passes before it, at any thread count.
  s.transport.weight_log = nullptr;
  vrlis::integration::VrlRenderer a(built->scene, s);
  a.set_effort_price(learned);
  const vrlis::integration::Film original = a.RenderPass(1, 3, nullptr);
  CheckPassFromPrice(*built, s, learned, original);
  // The model acts: the cheapest model in both gathers, the pass is equiangular sampling's
  // but in the few pixels that explore the rule (EffortPrice::kExplore, 1 in 512 per gather kind).
  s.transport.sampling = *vrlis::ParseGatherSamplers("equiangular");
  const vrlis::integration::Film fixed = vrlis::integration::VrlRenderer(built->scene, s).RenderPass(1, 3, nullptr);
  int differ = 0;
  for (std::size_t i = 0; i < fixed.pixels.size(); ++i)
    differ += std::memcmp(&fixed.pixels[i], &original.pixels[i], sizeof fixed.pixels[i]) != 0;
  INFO(differ << " pixels differ from equiangular sampling's");
  CHECK(differ <= 4);
}

// A pair (GatherOptions::pair) is for the statistics alone: the call returns what it returns
// without one and leaves the same numbers to the rest of the path, and its record's sum less
// the pixel's is what the accurate model, taken on the same numbers, would have added instead.
TEST_CASE("effort: a pair changes no gather and measures the accurate model on the same numbers",
          "[render][effort]") {
  using namespace vrlis::integration;
  auto built = EffortScene("bidirectional");
  REQUIRE(built);
  const Scene& scene = built->scene;
  const std::vector<Vrl> vrls = TraceLightPaths(scene, built->transport, 32, 1, 0);
  REQUIRE(vrls.size() > 8);
  const vrlis::GatherSamplers method = *vrlis::ParseGatherSamplers("auto");
  GatherOptions rule;
  rule.effort.medium.on = true, rule.effort.medium.decide = false;
  rule.effort.pair = rule.effort.medium;
  rule.effort.pair.model = vrlis::EffortModel::Accurate;
  GatherOptions accurate;
  accurate.effort.medium = rule.effort.pair;
  const Spectrum throughput(0.5f);
  int segments = 0;
  for (int pixel = 0; pixel < 16; ++pixel) {
    const Ray ray = scene.camera.Generate(4.f * (pixel % 4) + 2.f, 4.f * (pixel / 4) + 2.f, 16, 16);
    SurfaceHit hit;
    const bool found = scene.Intersect(ray, &hit);
    const CameraSegment seg{ray, scene.medium.Clip(ray, found ? hit.t : kInfinity)};
    if (seg.iv.Empty()) continue;
    ++segments;
    Rng a(1, 0, static_cast<std::uint64_t>(pixel), StreamPurpose::Camera), b = a, c = a;
    vrlis::PixelRecord plain, paired;
    GatherOptions alone_options = rule, pair_options = rule;
    alone_options.effort.record = &plain;
    pair_options.effort.record = &paired, pair_options.pair = true;
    const Spectrum alone = GatherMediumToMedium(method, scene, seg, vrls, a, throughput, alone_options);
    const Spectrum with_pair = GatherMediumToMedium(method, scene, seg, vrls, b, throughput, pair_options);
    const Spectrum instead = GatherMediumToMedium(method, scene, seg, vrls, c, throughput, accurate);
    CHECK(std::memcmp(&alone, &with_pair, sizeof(Spectrum)) == 0);
    CHECK(a.Uniform() == b.Uniform());
    CHECK(paired.pair.model_samples[static_cast<int>(vrlis::EffortModel::Accurate)] > 0);
    CHECK(paired.pair.work > 0);
    CHECK(plain.pair.calls == 0);
    // The scene's light is grey: the RMS of a sum is the sum of the RMS.
    const double measured = (throughput * with_pair).Rms() + (paired.pair.sum - paired.medium.sum);
    const double expected = (throughput * instead).Rms();
    INFO("pixel " << pixel << ": accurate " << expected << ", rule + delta " << measured);
    CHECK(measured == Approx(expected).epsilon(1e-4).margin(1e-9));
  }
  CHECK(segments > 8);
}

// Passes of 8 x 8 pixels whose values alternate 1.1 and 0.9 at 5000 work units a pixel, each
// pixel taking 10 samples of the rule, at 400 in the odd pixels and measuring the mixture's
// added variance, `excess[pass]` a pixel, in the even ones; the first pass's pixel 1 also takes
// 10 samples of the mixture at 200. The refreshes after passes 2, 3 and 4 weigh: V = 0.02, then
// 0.04 / 3, the mixture's change of V the mean excess so far and of T -2000 of 5000. So a
// mixture taken pays where (V + excess) 0.6 < V, by the margin a change must pay
// (kSwitchMargin) where it is below 0.9 V.
TEST_CASE("effort: the price changes the image's model where V x T is less by a margin", "[render][effort]") {
  using vrlis::EffortModel;
  constexpr int kRule = static_cast<int>(EffortModel::Chosen), kMixture = static_cast<int>(EffortModel::Mixture);
  auto model = [](std::vector<double> excess) {
    constexpr int kSide = 8;
    vrlis::EffortPrice price(kSide, kSide);
    for (std::size_t pass = 0; pass < excess.size(); ++pass) {
      price.BeginPass(vrlis::EffortSettings{true});
      for (int i = 0; i < kSide * kSide; ++i) {
        vrlis::EffortRecord& p = price.Pixel(i % kSide, i / kSide, [] { return 0.5; }).record->medium;
        p.calls = 1, p.samples = 10, p.work = 5e3, p.predicted = p.measured = 1;  // priced from the second pass
        p.model_samples[kRule] = 10;
        if (i % 2) p.model_work[kRule] = 10 * 400.0;
        else p.mixture_measured = 10, p.mixture_excess = excess[pass];
        if (pass == 0 && i == 1) p.samples += 10, p.model_samples[kMixture] = 10, p.model_work[kMixture] = 10 * 200.0;
      }
      price.EndPass(std::vector<double>(kSide * kSide, pass % 2 ? 0.9 : 1.1));
    }
    return price.model(vrlis::GatherKind::Medium);
  };
  auto constant = [&](double excess) { return model(std::vector<double>(5, excess)); };
  CHECK(constant(0.002) == EffortModel::Mixture);  // 0.66 V T, then 0.69
  CHECK(constant(0.007) == EffortModel::Mixture);  // 0.81 V T, then 0.92: the rule to first order
  CHECK(constant(0.012) == EffortModel::Chosen);   // 0.96 V T, then 1.14
  CHECK(constant(0.02) == EffortModel::Chosen);    // 1.2 V T, then 1.5
  // Mean excess 0.012, 0.010, 0.0088: 0.96, 1.05, 0.996 V T, never by the margin.
  CHECK(model({0.012, 0.012, 0.012, 0.004, 0.004}) == EffortModel::Chosen);
  // Taken at 0.66 V T (mean excess 0.002), the mixture is kept where the rule then beats it
  // within the margin (mean 0.0065, 0.0092: 0.89, 1.014 V T), and left where by more (0.014:
  // 1.23 V T).
  CHECK(model({0.002, 0.002, 0.002, 0.02, 0.02}) == EffortModel::Mixture);
  CHECK(model({0.002, 0.002, 0.002, 0.05, 0.05}) == EffortModel::Chosen);
}

// Passes of 8 x 8 pixels whose values alternate 1.1 and 0.9 (neighbours' variance 0.02) at 5000
// a pixel, each pixel taking 10 samples of the rule at 400; the first pass pairs them with
// the accurate model, whose pixels would have been 1 +- 0.1 x `spread` (variance 0.02 x
// spread^2) at `work` a sample. With a change of the model worth kAccurateMargin, the
// accurate model pays where 0.02 spread^2 (5000 + 10 (work - 400)) < 0.8 x 0.02 x 5000,
// and it is decided at the first price only.
TEST_CASE("effort: the accurate model is taken where its pairs' image is worth the time, once",
          "[render][effort]") {
  using vrlis::EffortModel;
  constexpr int kRule = static_cast<int>(EffortModel::Chosen), kAccurate = static_cast<int>(EffortModel::Accurate);
  auto model = [](double spread, double work, int passes, bool paired) {
    constexpr int kSide = 8;
    vrlis::EffortPrice price(kSide, kSide);
    for (int pass = 0; pass < passes; ++pass) {
      price.BeginPass(vrlis::EffortSettings{true});
      std::vector<double> values(kSide * kSide);
      for (int i = 0; i < kSide * kSide; ++i) {
        values[std::size_t(i)] = i % 2 ? 0.9 : 1.1;
        vrlis::PixelRecord& r = *price.Pixel(i % kSide, i / kSide, [] { return 0.5; }).record;
        vrlis::EffortRecord& p = r.medium;
        p.calls = 1, p.samples = 10, p.work = 5e3, p.predicted = p.measured = 1;
        p.model_samples[kRule] = 10, p.model_work[kRule] = 10 * 400.0;
        if (pass == 0 && paired) {
          r.pair.calls = 1, r.pair.model_samples[kAccurate] = 10, r.pair.model_work[kAccurate] = 10 * work;
          r.pair.sum = (values[std::size_t(i)] - 1) * (spread - 1);
        }
      }
      price.EndPass(values);
    }
    return price.model(vrlis::GatherKind::Medium);
  };
  CHECK(model(0.3, 2e3, 1, true) == EffortModel::Accurate);   // V / 11 at 4.2 times T
  CHECK(model(0.3, 6e3, 1, true) == EffortModel::Chosen);     // V / 11 at 12 times T
  CHECK(model(0.9, 5e2, 1, true) == EffortModel::Chosen);     // V x 0.81 at 1.2 times T: within the margin
  CHECK(model(0.3, 2e3, 1, false) == EffortModel::Chosen);    // no pairs, no measure of it
  CHECK(model(0.3, 2e3, 6, true) == EffortModel::Accurate);   // kept in the passes after
}

// The pilot's probe (EffortPrice::EndProbe): an 8 x 8 image whose probe pixels alternate 1.1
// and 0.9 (neighbours' variance 0.02), each with `m2` as its medium-to-medium samples' sum of
// squares. The accurate model can remove at most that much variance; below 1 - kAccurateMargin
// of 0.02 (0.004) it cannot pay, and the rest of the pilot pairs no pixel.
TEST_CASE("effort: the pilot pairs pixels only where its probe shows the accurate model could pay",
          "[render][effort]") {
  constexpr int kSide = 8;
  auto pairs = [](double m2, bool probed) {
    vrlis::EffortPrice price(kSide, kSide);
    price.BeginPass(vrlis::EffortSettings{true});
    std::vector<double> values(kSide * kSide, std::numeric_limits<double>::quiet_NaN());
    for (int i = 0; i < kSide * kSide; ++i) {
      const int x = i % kSide, y = i / kSide;
      if (!vrlis::EffortPrice::InProbe(x, y)) continue;
      values[std::size_t(i)] = x % 2 ? 0.9 : 1.1;
      price.Pixel(x, y, [] { return 0.5; }).record->medium.sum_sq = m2;
    }
    if (probed) price.EndProbe(values);
    int paired = 0, probe_paired = 0;
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x)
        if (vrlis::EffortPrice::InPilot(x, y) && price.Pairs(x, y, 0.5))
          ++(vrlis::EffortPrice::InProbe(x, y) ? probe_paired : paired);
    CHECK(probe_paired == 0);  // the probe's own pixels never pair
    return paired;
  };
  CHECK(pairs(0.003, true) == 0);
  CHECK(pairs(0.005, true) == 14);  // the other 14 of the tile's 16 pilot pixels
  CHECK(pairs(0.003, false) == 14);  // without a probe, as before one
}

TEST_CASE("effort: gathers are decided one by one only where the decisions pay", "[render][effort]") {
  auto decide = [](const char* scene, float g, const char* sampler) {
    vrlis::scenes::MediumOverrides medium;
    medium.g = g;
    auto built = vrlis::scenes::BuildScene(scene, medium);
    REQUIRE(built);
    vrlis::integration::RenderSettings s = Settings(*built, 24, true);
    s.transport.sampling = *vrlis::ParseGatherSamplers(sampler);
    vrlis::integration::VrlRenderer r(built->scene, s);
    for (std::uint64_t pass = 0; pass < 6; ++pass) r.RenderPass(1, pass, nullptr);
    return r.effort_price().decisions_pay(vrlis::GatherKind::Medium);
  };
  CHECK(decide("room", 0.5f, "equiangular"));
  CHECK_FALSE(decide("bidirectional", 0.f, "equiangular"));
}
