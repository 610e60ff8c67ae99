// Rejected gather queries are counted by reason (core/query_rejections.hpp): each kind of bad
// input adds exactly one to its own reason per rejection, through every entry point a renderer
// calls, and valid queries add nothing.
#include <catch2/catch.hpp>
#include <vrlis/vrlis.hpp>

#include <limits>

#include "extern_gathers.hpp"

namespace {

using E = vrlis::QueryError;

vrlis::MediumGatherQuery<float> Good() {
  return {{{0, 0, 0}, {0, 0, -1}, 0, 10}, {{1, 0, -3}, {0, 1, 0}, 5},
          vrlis::Medium<float>::FromAbsorptionScattering(0.5f, 0.1f, 0.3f)};
}

std::uint64_t Count(const vrlis::QueryRejections& r, E e) { return r.count[static_cast<int>(e)]; }

TEST_CASE("rejected gather queries are counted by reason", "[gather][rejections]") {
  const vrlis::GatherSamplers method = *vrlis::ParseGatherSamplers("cauchy-sum");
  const vrlis::QueryRejections start = vrlis::RejectedQueries();

  SECTION("valid queries count nothing") {
    for (int i = 0; i < 100; ++i) CHECK(vrlis::SampleMediumGather(method, Good(), 0.3f, 0.6f).contributes());
    CHECK(vrlis::RejectedQueries().since(start).total() == 0);
  }

  SECTION("each rejection adds one to its reason") {
    vrlis::MediumGatherQuery<float> swapped = Good();
    swapped.medium = vrlis::Medium<float>::FromScatteringExtinction(0.5f, 0.4f, 0.3f);  // sigma_s and sigma_t swapped
    vrlis::MediumGatherQuery<float> tilted = Good();
    tilted.camera.dir = {0, 0.5f, -1};
    for (int i = 0; i < 7; ++i) CHECK(vrlis::SampleMediumGather(method, swapped, 0.3f, 0.6f).weight == 0);
    for (int i = 0; i < 3; ++i) CHECK(vrlis::SampleMediumGather(method, tilted, 0.3f, 0.6f).weight == 0);
    vrlis::SurfaceGatherQuery<float> surface{{0, -1, -2}, {0, 2, 0}, Good().vrl, Good().medium};
    CHECK(vrlis::SampleSurfaceGather(method.segment, surface, 0.5f).weight == 0);
    vrlis::PointLightGatherQuery<float> light{Good().camera, {0, std::numeric_limits<float>::infinity(), 0}, Good().medium};
    CHECK(vrlis::SamplePointLightGather(method.segment, light, 0.5f).weight == 0);

    const vrlis::QueryRejections r = vrlis::RejectedQueries().since(start);
    CHECK(Count(r, E::ScatteringExceedsExtinction) == 7);
    CHECK(Count(r, E::NotUnitDirection) == 3 + 1);
    CHECK(Count(r, E::NonFinite) == 1);
    CHECK(r.total() == 12);
    CHECK(vrlis::Describe(r) ==
          "1 non-finite input, 4 direction is not unit length, 7 scattering coefficient above extinction "
          "(sigma_t = sigma_a + sigma_s; see Medium's factories)");
  }

  SECTION("the one-call gather counts a rejected camera segment once and each rejected VRL") {
    vrlis::VrlSegment<float> vrls[3] = {Good().vrl, Good().vrl, Good().vrl};
    vrls[1].length = -1;
    int taken = 0;
    auto uniform = [] { return 0.5f; };
    auto connect = [&](int, const vrlis::GatherSample<float>&, float) { ++taken; };
    vrlis::GatherMediumVrls(method, Good().camera, Good().medium, vrls, 3, uniform, connect);
    CHECK(taken == 2);
    vrlis::RaySegment<float> reversed = Good().camera;
    reversed.tmax = -1;
    vrlis::GatherMediumVrls(method, reversed, Good().medium, vrls, 3, uniform, connect);
    CHECK(taken == 2);
    const vrlis::QueryRejections r = vrlis::RejectedQueries().since(start);
    CHECK(Count(r, E::ReversedSegment) == 2);
    CHECK(r.total() == 2);
  }
}

}  // namespace
