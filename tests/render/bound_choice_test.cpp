// The VRL bound chosen per image by the price of variance (vrlis_integration/bound_choice.hpp):
// - the choice takes the candidate whose pilot pixels showed the least variance times work, and
//   only after the two pilot passes, each of which gives every candidate its share of pixels;
// - a render that chooses keeps the image's mean: block by block within the noise of the
//   unbounded render, in the cloud, where the candidates' variances differ most; a sabotage
//   that picks, per pass, the candidate whose image came out darker (a choice that reads the
//   pass it acts on) is rejected, so the test has power;
// - a render that chooses is a function of its seed.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <vrlis_scenes/scenes.hpp>

#include "block_stats.hpp"
#include "uncontrolled.hpp"

namespace {

namespace vi = vrlis::integration;

TEST_CASE("BoundChoice: the pilot shares the pixels, then the least variance times work wins", "[render][bound]") {
  vi::BoundChoice choice({vi::kUnbounded, 1.f, 0.f});
  REQUIRE(choice.active());
  const int width = 6, height = 4;
  int seen[3] = {0, 0, 0};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float b = choice.Bound(x, y);
      seen[b == vi::kUnbounded ? 0 : b == 1.f ? 1 : 2] += 1;
    }
  CHECK(seen[0] == 8);
  CHECK(seen[1] == 8);
  CHECK(seen[2] == 8);
  CHECK(choice.LightPaths());
  // Pass values whose pass-to-pass differences give each candidate a variance, and works:
  // unbounded variance 4, work 1 (price 4); bound 1: 1 and 2 (2); bound 0: 0.25 and 16 (4).
  const double spread[3] = {2, 1, 0.5}, work[3] = {1, 2, 16};
  std::vector<double> first(width * height), second(width * height), w(width * height);
  for (int i = 0; i < width * height; ++i) {
    const float b = choice.Bound(i % width, i / width);
    const int k = b == vi::kUnbounded ? 0 : b == 1.f ? 1 : 2;
    first[i] = 10 + spread[k] * 0.5 * std::sqrt(2.0) * (i % 2 ? 1 : -1);
    second[i] = 10 - spread[k] * 0.5 * std::sqrt(2.0) * (i % 2 ? 1 : -1);
    w[i] = work[k];
  }
  choice.EndPass(width, first, w, 0);
  CHECK_FALSE(choice.chosen());
  choice.EndPass(width, second, w, 0);
  REQUIRE(choice.chosen());
  CHECK(*choice.chosen() == 1.f);
  CHECK(choice.Bound(0, 0) == 1.f);
  CHECK(choice.candidates()[0].variance == Approx(4));
  CHECK(choice.candidates()[2].Price() == Approx(4));
  // The light pass's work is the lit candidates' alone: with enough of it the path tracer wins.
  vi::BoundChoice lit({vi::kUnbounded, 1.f, 0.f});
  lit.EndPass(width, first, w, 0);
  lit.EndPass(width, second, w, 100.0 * width * height);
  REQUIRE(lit.chosen());
  CHECK(*lit.chosen() == 0.f);
  CHECK_FALSE(lit.LightPaths());
}

// A sabotage: per pass, both candidates rendered and the darker image kept.
class DarkerOfTwo : public vi::Renderer {
 public:
  DarkerOfTwo(const vi::Scene& scene, const vi::RenderSettings& a, const vi::RenderSettings& b)
      : Renderer(scene, a), a_(scene, a), b_(scene, b) {}
  vi::Film RenderPass(std::uint64_t seed, std::uint64_t pass, vi::PassStats*) override {
    vi::Film f = a_.RenderPass(seed, pass, nullptr), g = b_.RenderPass(seed, pass, nullptr);
    auto sum = [](const vi::Film& film) {
      double s = 0;
      for (const vi::Spectrum& p : film.pixels) s += p.MeanSquare();
      return s;
    };
    return sum(f) < sum(g) ? f : g;
  }

 private:
  vi::VrlRenderer a_, b_;
};

vi::RenderSettings CloudSettings(const vrlis::scenes::BuiltScene& built) {
  vi::RenderSettings s;
  s.width = s.height = 24;
  s.vrls_per_pass = 16;
  s.transport = vrlis::test::Uncontrolled(built.transport);
  s.transport.vrl_bound = vi::kUnbounded;
  return s;
}

TEST_CASE("BoundChoice: a render that chooses keeps the image's mean but not one that reads its own pass",
          "[render][bound]") {
  auto built = vrlis::scenes::BuildScene("cloud", {});
  REQUIRE(built);
  const vi::RenderSettings whole_settings = CloudSettings(*built);
  vi::RenderSettings choosing_settings = whole_settings, traced_settings = whole_settings;
  choosing_settings.vrl_bounds = vi::kAutoBounds;
  traced_settings.transport.vrl_bound = 0;
  vi::VrlRenderer whole(built->scene, whole_settings), choosing(built->scene, choosing_settings);
  DarkerOfTwo sabotage(built->scene, whole_settings, traced_settings);
  const int block = 12, passes = 600;
  auto w = vrlis::test::EstimateBlocks(whole, 24, 24, block, passes, 41);
  auto c = vrlis::test::EstimateBlocks(choosing, 24, 24, block, passes, 42);
  auto s = vrlis::test::EstimateBlocks(sabotage, 24, 24, block, passes, 42);
  const vrlis::test::ZSummary z = vrlis::test::Compare(c, w), zs = vrlis::test::Compare(s, w);
  std::printf("[bound choice] chose %g: %s\n[bound choice] sabotage, the darker pass kept: %s\n",
              double(choosing.bound_choice().chosen().value_or(-1)), z.Describe().c_str(), zs.Describe().c_str());
  REQUIRE(choosing.bound_choice().chosen());
  CHECK(z.n == 4);
  CHECK(z.Pass());
  CHECK_FALSE(zs.Pass());
}

TEST_CASE("BoundChoice: a render that chooses is a function of its seed", "[render][bound]") {
  auto built = vrlis::scenes::BuildScene("cloud", {});
  REQUIRE(built);
  vi::RenderSettings s = CloudSettings(*built);
  s.vrl_bounds = vi::kAutoBounds;
  s.transport.effort.on = true;
  auto render = [&] {
    vi::VrlRenderer r(built->scene, s);
    std::vector<vi::Film> films;
    for (std::uint64_t pass = 0; pass < 4; ++pass) films.push_back(r.RenderPass(5, pass, nullptr));
    return films;
  };
  const std::vector<vi::Film> a = render(), b = render();
  for (std::size_t p = 0; p < a.size(); ++p)
    CHECK(std::memcmp(a[p].pixels.data(), b[p].pixels.data(), a[p].pixels.size() * sizeof(vi::Spectrum)) == 0);
}

}  // namespace
