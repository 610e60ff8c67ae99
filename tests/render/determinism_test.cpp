// The same seed gives the same image whatever the thread count: random streams are named
// by (seed, pass, pixel or light path), never by thread, and the effort control prices
// counted work, never a clock reading.
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

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

namespace {

// The bytes of the file with extension `ext` (the EXR, or the JSON summary) vrl_render writes
// for these arguments (empty if it failed).
std::string RenderFile(const std::string& args, const char* ext = ".exr") {
  const std::string stem = "determinism_" + std::to_string(getpid());
  const std::string cmd = std::string(VRL_RENDER) + " --quiet " + args + " --out " + stem + ".exr";
  if (std::system(cmd.c_str()) != 0) return {};
  std::ifstream in(stem + ext, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  for (const char* ext : {".exr", ".png", ".json"}) std::remove((stem + ext).c_str());
  return bytes.str();
}

}  // namespace

TEST_CASE("vrl_render's defaults, the effort control on, give the same file at 1, 2 and all threads",
          "[render][determinism]") {
  for (std::string_view name : vrlis::scenes::kSceneNames) {
    INFO(name);
    const std::string args = "--scene " + std::string(name) + " --width 16 --height 16 --spp 6 --seed 3";
    const std::string one = RenderFile(args + " --threads 1");
    REQUIRE_FALSE(one.empty());
    CHECK(RenderFile(args + " --threads 2") == one);
    CHECK(RenderFile(args + " --threads 0") == one);
    CHECK(RenderFile("--scene " + std::string(name) + " --width 16 --height 16 --spp 6 --seed 4 --threads 1") != one);
  }
}

TEST_CASE("one default: the library's samplers are the integration layer's and vrl_render's", "[render][default]") {
  const vrlis::integration::TransportSettings transport;
  CHECK(transport.sampling == vrlis::GatherSamplers{});
  CHECK(transport.effort.on);
  std::string summary = RenderFile("--scene room --width 4 --height 4 --spp 1", ".json");
  summary.erase(std::remove(summary.begin(), summary.end(), ' '), summary.end());
  INFO(summary);
  CHECK(summary.find("\"sampler\":\"" + vrlis::Name(vrlis::GatherSamplers{}) + "\"") != std::string::npos);
  CHECK(summary.find("\"effort\":\"on\"") != std::string::npos);
}
