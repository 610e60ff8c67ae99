// The VPL gather and the path-traced remainder share the surface-to-surface connections
// (vrlis_integration/vpl.hpp): the VPLs' part up to the bound plus the remainder's share of
// the rest must equal the remainder alone, block by block within the noise. The sabotage (the
// remainder not giving up the VPLs' part, so that it counts twice; or giving up the share of a
// bound twice the VPLs', so that the connections between the two go missing) must be
// rejected, so the test has power.
#include <catch2/catch.hpp>

#include <cstdio>
#include <memory>
#include <utility>

#include <vrlis_scenes/scenes.hpp>

#include "block_stats.hpp"

namespace {

namespace vi = vrlis::integration;
using vi::RenderSettings;
using vi::VrlRenderer;

// The sum of two renders' passes (their parts of transport).
class SumRenderer : public vi::Renderer {
 public:
  SumRenderer(const vi::Scene& scene, const RenderSettings& a, const RenderSettings& b)
      : Renderer(scene, a), a_(scene, a), b_(scene, b) {}
  vi::Film RenderPass(std::uint64_t seed, std::uint64_t pass, vi::PassStats*) override {
    vi::Film f = a_.RenderPass(seed, pass, nullptr), g = b_.RenderPass(seed, pass, nullptr);
    for (std::size_t i = 0; i < f.pixels.size(); ++i) f.pixels[i] += g.pixels[i];
    return f;
  }

 private:
  VrlRenderer a_, b_;
};

// One part of the transport alone: the VPLs' (surface to surface) or the remainder's.
RenderSettings Part(const RenderSettings& base, bool vpls, float bound) {
  RenderSettings s = base;
  vi::TransportSettings& t = s.transport;
  t.medium_to_medium = t.medium_to_surface = t.direct = false;
  t.surface_to_surface = t.surface_to_medium = vpls;
  t.indirect = !vpls;
  t.vpl_bound = bound;
  return s;
}

}  // namespace

TEST_CASE("VPLs and the remainder share surface-to-surface light without bias", "[render][vpl]") {
  auto built = vrlis::scenes::BuildScene("cube", {});
  REQUIRE(built);
  RenderSettings base;
  base.width = base.height = 32;
  base.vrls_per_pass = 32;
  base.transport = built->transport;
  base.transport.light_caustics = false;  // caustic light paths make no VPLs anyway: fewer wasted paths
  const float bound = 0.1f;  // near the scene's typical geometry terms: the remainder's share is large
  const int block = 16, passes = 600;
  VrlRenderer whole(built->scene, Part(base, false, 0));  // the remainder carries every connection
  SumRenderer split(built->scene, Part(base, true, bound), Part(base, false, bound));
  SumRenderer twice(built->scene, Part(base, true, bound), Part(base, false, 0));  // sabotages
  SumRenderer gap(built->scene, Part(base, true, bound), Part(base, false, 2 * bound));
  auto w = vrlis::test::EstimateBlocks(whole, base.width, base.height, block, passes, 21);
  auto s = vrlis::test::EstimateBlocks(split, base.width, base.height, block, passes, 22);
  auto t = vrlis::test::EstimateBlocks(twice, base.width, base.height, block, passes, 22);
  auto g = vrlis::test::EstimateBlocks(gap, base.width, base.height, block, passes, 22);
  vrlis::test::ZSummary z = vrlis::test::Compare(s, w), zt = vrlis::test::Compare(t, w), zg = vrlis::test::Compare(g, w);
  std::printf("[vpl] split vs remainder alone: %s\n[vpl] sabotage, no share given up: %s\n"
              "[vpl] sabotage, the share of twice the bound given up: %s\n",
              z.Describe().c_str(), zt.Describe().c_str(), zg.Describe().c_str());
  CHECK(z.n == 4);
  CHECK(z.Pass());
  CHECK_FALSE(zt.Pass());
  CHECK_FALSE(zg.Pass());
}
