// The VRL renderer against the reference path tracer, scene by scene, at low resolution:
// per-block means over independent passes, z-scores, Bonferroni-corrected. A negative
// control (the VRL image scaled by 1.15) must be rejected, so the test has power.
#include <catch2/catch.hpp>

#include <cstdio>

#include <vrlis_scenes/scenes.hpp>

#include "block_stats.hpp"
#include "uncontrolled.hpp"

namespace {

struct Case {
  const char* scene;
  vrlis::SegmentChoice method;
  int size, block;  // image and block size in pixels
  int vrl_passes, vrls, pt_passes;
  double control;  // a radiometric error the test must detect at this budget
};

void Run(const Case& c) {
  auto built = vrlis::scenes::BuildScene(c.scene, {});
  REQUIRE(built);
  vrlis::integration::RenderSettings s;
  s.width = s.height = c.size;
  s.vrls_per_pass = c.vrls;
  s.transport = vrlis::test::Uncontrolled(built->transport);
  s.transport.sampling.segment = c.method;
  s.transport.light_caustics = false;  // the path tracer cannot sample L S+ paths from point lights
  const int block = c.block;
  vrlis::integration::VrlRenderer vrl(built->scene, s);
  vrlis::integration::PathTracingRenderer pt(built->scene, s);
  auto a = vrlis::test::EstimateBlocks(vrl, s.width, s.height, block, c.vrl_passes, 11);
  auto b = vrlis::test::EstimateBlocks(pt, s.width, s.height, block, c.pt_passes, 12);
  vrlis::test::ZSummary z = vrlis::test::Compare(a, b);
  double ra = 0, rb = 0;
  for (std::size_t k = 0; k < a.mean.size(); ++k) {
    ra += a.stderr_[k] / a.mean[k] / a.mean.size();
    rb += b.stderr_[k] / b.mean[k] / b.mean.size();
  }
  std::printf("[render] %s: mean relative standard error VRL %.3f, path tracer %.3f\n", c.scene, ra, rb);
  std::printf("[render] %s, %s vs path tracer: %s\n", c.scene, std::string(vrlis::Name(c.method)).c_str(),
              z.Describe().c_str());
  CHECK(z.n == (c.size / c.block) * (c.size / c.block));
  CHECK(z.Pass());
  // Negative control: a radiometric error of c.control must be detected.
  auto scaled = a;
  for (double& m : scaled.mean) m *= c.control;
  for (double& e : scaled.stderr_) e *= c.control;
  vrlis::test::ZSummary zc = vrlis::test::Compare(scaled, b);
  std::printf("[render] %s, control x%.2f: %s\n", c.scene, c.control, zc.Describe().c_str());
  CHECK_FALSE(zc.Pass());
}

// Each scene checks another sampler, in registry order after the first (the cost floor, which
// the other tests cover most), so that one run puts several samplers against the reference.
vrlis::SegmentChoice NthSampler(std::size_t k) { return vrlis::kSegmentSamplers[k % vrlis::kSegmentSamplers.size()]; }

}  // namespace

TEST_CASE("room: VRL image matches the path tracer", "[render][reference]") {
  Run({"room", NthSampler(1), 32, 16, 480, 4, 2048, 1.25});
}

TEST_CASE("cube: VRL image matches the path tracer", "[render][reference]") {
  Run({"cube", NthSampler(2), 32, 8, 48, 32, 256, 1.1});
}

TEST_CASE("corner: VRL image matches the path tracer", "[render][reference]") {
  Run({"corner", NthSampler(3), 16, 16, 200, 64, 4096, 1.25});
}

TEST_CASE("cloud: VRL image matches the path tracer", "[render][reference]") {
  Run({"cloud", NthSampler(4), 32, 16, 96, 32, 1024, 1.1});
}

TEST_CASE("fog: VRL image matches the path tracer", "[render][reference]") {
  Run({"fog", NthSampler(5), 16, 8, 512, 16, 2048, 1.2});
}
