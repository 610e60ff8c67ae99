// The same seed gives the same image whatever the thread count: random streams are named
// by (seed, pass, pixel or light path), never by thread.
#include <tbb/global_control.h>

#include <catch2/catch.hpp>
#include <cstring>

#include <vrlis_scenes/scenes.hpp>

#include "vrlis_integration/renderer.hpp"

namespace {

vrlis::integration::Film Render(const vrlis::integration::Scene& scene, const vrlis::integration::RenderSettings& s, int threads, std::uint64_t seed) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  vrlis::integration::VrlRenderer r(scene, s);
  vrlis::integration::Accumulator acc(s.width, s.height);
  for (std::uint64_t pass = 0; pass < 2; ++pass) acc.Add(r.RenderPass(seed, pass, nullptr));
  return acc.Mean();
}

bool Same(const vrlis::integration::Film& a, const vrlis::integration::Film& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(vrlis::integration::Spectrum)) == 0;
}

}  // namespace

TEST_CASE("an image does not depend on the thread count, and does on the seed", "[render][determinism]") {
  for (const char* name : {"room", "cube"}) {
    auto built = vrlis::scenes::BuildScene(name, {});
    REQUIRE(built);
    vrlis::integration::RenderSettings s;
    s.width = s.height = 24;
    s.vrls_per_pass = 64;
    s.transport = built->transport;
    vrlis::integration::Film one = Render(built->scene, s, 1, 7), four = Render(built->scene, s, 4, 7);
    CHECK(Same(one, four));
    CHECK_FALSE(Same(one, Render(built->scene, s, 4, 8)));
  }
}
