// Gathers and the path-traced remainder share connections (vrlis_integration/share.hpp): the
// VPLs the surface-to-surface ones, the VRL gathers those from camera vertices to medium
// points. The gathers' part up to the bound plus the remainder's share of the rest must equal
// the unshared transport, block by block within the noise. The sabotages (the remainder not
// giving up the gathers' part, so that it counts twice; or giving up more than the gathers
// take, so that connections go missing) must be rejected, so the tests have power.
#include <catch2/catch.hpp>

#include <cstdio>
#include <memory>
#include <utility>

#include <vrlis_scenes/scenes.hpp>

#include "block_stats.hpp"
#include "uncontrolled.hpp"

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

// The split render against the unshared one, block by block, and the two sabotages, which
// must be rejected (seed: the unshared render's; the others share seed + 1).
void CheckShare(const char* what, vi::Renderer& whole, vi::Renderer& split, vi::Renderer& twice, vi::Renderer& gap,
                int size, int block, int passes, std::uint64_t seed) {
  auto w = vrlis::test::EstimateBlocks(whole, size, size, block, passes, seed);
  auto s = vrlis::test::EstimateBlocks(split, size, size, block, passes, seed + 1);
  auto t = vrlis::test::EstimateBlocks(twice, size, size, block, passes, seed + 1);
  auto g = vrlis::test::EstimateBlocks(gap, size, size, block, passes, seed + 1);
  vrlis::test::ZSummary z = vrlis::test::Compare(s, w), zt = vrlis::test::Compare(t, w), zg = vrlis::test::Compare(g, w);
  std::printf("[%s] split vs unshared: %s\n[%s] sabotage, no share given up: %s\n"
              "[%s] sabotage, more given up than the gathers take: %s\n",
              what, z.Describe().c_str(), what, zt.Describe().c_str(), what, zg.Describe().c_str());
  CHECK(z.n == 4);
  CHECK(z.Pass());
  CHECK_FALSE(zt.Pass());
  CHECK_FALSE(zg.Pass());
}

// One part of the transport alone: the VPLs' (surface to surface) or the remainder's.
RenderSettings VplPart(const RenderSettings& base, bool vpls, float bound) {
  RenderSettings s = base;
  vi::TransportSettings& t = s.transport;
  t.medium_to_medium = t.medium_to_surface = t.direct = false;
  t.surface_to_surface = t.surface_to_medium = vpls;
  t.indirect = !vpls;
  t.vpl_bound = bound;
  return s;
}

}  // namespace

TEST_CASE("VPLs and the remainder share surface-to-surface light without bias", "[render][share]") {
  auto built = vrlis::scenes::BuildScene("cube", {});
  REQUIRE(built);
  RenderSettings base;
  base.width = base.height = 32;
  base.vrls_per_pass = 32;
  base.transport = vrlis::test::Uncontrolled(built->transport);
  base.transport.light_caustics = false;  // caustic light paths make no VPLs anyway: fewer wasted paths
  const float bound = 0.1f;  // near the scene's typical geometry terms: the remainder's share is large
  const int block = 16, passes = 600;
  VrlRenderer whole(built->scene, VplPart(base, false, 0));  // the remainder carries every connection
  SumRenderer split(built->scene, VplPart(base, true, bound), VplPart(base, false, bound));
  SumRenderer twice(built->scene, VplPart(base, true, bound), VplPart(base, false, 0));  // sabotages
  SumRenderer gap(built->scene, VplPart(base, true, bound), VplPart(base, false, 2 * bound));
  CheckShare("vpl", whole, split, twice, gap, base.width, block, passes, 21);
}

// One part of the transport alone: the two VRL gathers' or the remainder's (no VPLs).
RenderSettings VrlPart(const RenderSettings& base, bool gathers, float bound) {
  RenderSettings s = base;
  vi::TransportSettings& t = s.transport;
  t.direct = t.surface_to_surface = t.surface_to_medium = false;
  t.vpl_bound = 0;
  t.medium_to_medium = t.medium_to_surface = gathers;
  t.indirect = !gathers;
  t.vrl_bound = bound;
  return s;
}

TEST_CASE("VRL gathers and the remainder share medium connections without bias", "[render][share]") {
  auto built = vrlis::scenes::BuildScene("cloud", {});  // dense, bright medium over a floor: both gathers
  REQUIRE(built);
  RenderSettings base;
  base.width = base.height = 24;
  base.vrls_per_pass = 16;
  base.transport = vrlis::test::Uncontrolled(built->transport);
  const float bound = 1;  // connections shorter than 1: most of the dense cloud's
  const float none = vi::kUnbounded;
  const int block = 12, passes = 1000;
  SumRenderer whole(built->scene, VrlPart(base, true, none), VrlPart(base, false, none));
  SumRenderer split(built->scene, VrlPart(base, true, bound), VrlPart(base, false, bound));
  SumRenderer twice(built->scene, VrlPart(base, true, none), VrlPart(base, false, bound));  // sabotages
  SumRenderer gap(built->scene, VrlPart(base, true, bound), VrlPart(base, false, none));
  CheckShare("vrl share", whole, split, twice, gap, base.width, block, passes, 31);
}
