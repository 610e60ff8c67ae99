// Every gather query is validated the same way: each kind of bad input gives its QueryError
// and an estimate that contributes nothing (weight 0, never NaN); the edge of validity
// (an unbounded camera segment, a zero-length VRL, sigma_s = sigma_t) is accepted.
#include <catch2/catch.hpp>
#include <vrlis/vrlis.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

template <typename Real>
struct Mutation {
  const char* what;
  vrlis::QueryError expected;
  std::function<void(vrlis::MediumGatherQuery<Real>&)> apply;
};

template <typename Real>
vrlis::MediumGatherQuery<Real> Good() {
  return {{{0, 0, 0}, {0, 0, -1}, 0, 10}, {{1, 0, -3}, {0, 1, 0}, 5},
      vrlis::Medium<Real>::FromScatteringExtinction(Real(0.5), Real(0.3), Real(0.4))};
}

template <typename Real>
void MediumQueriesAreValidated() {
  using E = vrlis::QueryError;
  const Real inf = std::numeric_limits<Real>::infinity(), nan = std::numeric_limits<Real>::quiet_NaN();
  const Real huge = vrlis::MaxCoordinate<Real>() * 2;
  std::vector<Mutation<Real>> cases = {
      {"NaN camera origin", E::NonFinite, [&](auto& q) { q.camera.origin.x = nan; }},
      {"NaN camera tmax", E::NonFinite, [&](auto& q) { q.camera.tmax = nan; }},
      {"infinite VRL length", E::NonFinite, [&](auto& q) { q.vrl.length = inf; }},
      {"NaN g", E::NonFinite, [&](auto& q) { q.medium.g = nan; }},
      {"non-unit camera direction", E::NotUnitDirection, [](auto& q) { q.camera.dir.z = -2; }},
      {"non-unit VRL direction", E::NotUnitDirection, [](auto& q) { q.vrl.dir.y = Real(0.5); }},
      {"reversed camera segment", E::ReversedSegment, [](auto& q) { q.camera.tmax = -1; }},
      {"negative VRL length", E::ReversedSegment, [](auto& q) { q.vrl.length = -1; }},
      {"g = 1", E::InvalidAsymmetry, [](auto& q) { q.medium.g = 1; }},
      {"negative extinction", E::NegativeExtinction, [](auto& q) { q.medium.sigma_t = -1; }},
      {"scattering above extinction", E::ScatteringExceedsExtinction, [](auto& q) { q.medium.sigma_s = 1; }},
      {"negative scattering", E::NegativeScattering, [](auto& q) { q.medium.sigma_s = -Real(0.1); }},
      {"camera origin out of range", E::OutOfRange, [&](auto& q) { q.camera.origin.y = huge; }},
      {"VRL origin out of range", E::OutOfRange, [&](auto& q) { q.vrl.origin.x = -huge; }},
      {"unbounded camera segment", E::None, [&](auto& q) { q.camera.tmax = inf; }},
      {"zero-length VRL", E::None, [](auto& q) { q.vrl.length = 0; }},
      {"zero-length camera segment", E::None, [](auto& q) { q.camera.tmax = q.camera.tmin; }},
      {"sigma_s = sigma_t", E::None, [](auto& q) { q.medium.sigma_s = q.medium.sigma_t; }},
  };
  for (const auto& c : cases) {
    vrlis::MediumGatherQuery<Real> q = Good<Real>();
    c.apply(q);
    INFO(c.what);
    CHECK(vrlis::Validate(q) == c.expected);
    for (vrlis::VrlChoice one : vrlis::kVrlSamplers)
      for (vrlis::SegmentChoice two : vrlis::kSegmentSamplers) {
        INFO(vrlis::Name(vrlis::GatherSamplers{two, one}));
        for (Real u : {Real(0), Real(0.37), Real(1)}) {
          vrlis::GatherSample<Real> s = vrlis::SampleMediumGather(vrlis::GatherSamplers{two, one}, q, u, 1 - u);
          CHECK(std::isfinite(s.weight));
          CHECK(s.weight >= 0);
          if (c.expected != E::None) CHECK(s.weight == 0);
        }
      }
  }
}

}  // namespace

TEST_CASE("medium gather queries: each bad input has its error and contributes nothing (float)") {
  MediumQueriesAreValidated<float>();
}
TEST_CASE("medium gather queries: each bad input has its error and contributes nothing (double)") {
  MediumQueriesAreValidated<double>();
}

TEST_CASE("surface and point-light gather queries are validated") {
  using E = vrlis::QueryError;
  vrlis::SurfaceGatherQuery<float> s{{0, -1, -2}, {0, 1, 0}, {{-1, 0.5f, -2.5f}, {1, 0, 0}, 3},
      vrlis::Medium<float>::FromScatteringExtinction(0.5f, 0.3f, 0.4f)};
  CHECK(vrlis::Validate(s) == E::None);
  auto bad_normal = s;
  bad_normal.normal = {0, 0.5f, 0};
  CHECK(vrlis::Validate(bad_normal) == E::NotUnitDirection);
  auto nan_point = s;
  nan_point.point.z = std::nanf("");
  CHECK(vrlis::Validate(nan_point) == E::NonFinite);
  CHECK(vrlis::SampleSurfaceGather(vrlis::kSegmentSamplers[1], nan_point, 0.5f).weight == 0);

  vrlis::PointLightGatherQuery<float> p{{{0, 0, 0}, {0, 0, -1}, 0, 5}, {0.5f, 0, -2},
      vrlis::Medium<float>::FromScatteringExtinction(0.5f, 0.3f, 0.4f)};
  CHECK(vrlis::Validate(p) == E::None);
  auto reversed = p;
  reversed.camera.tmax = -1;
  CHECK(vrlis::Validate(reversed) == E::ReversedSegment);
  auto far_light = p;
  far_light.light.x = vrlis::MaxCoordinate<float>() * 2;
  CHECK(vrlis::Validate(far_light) == E::OutOfRange);
  CHECK(vrlis::SamplePointLightGather(vrlis::kSegmentSamplers[2], reversed, 0.5f).weight == 0);
}

TEST_CASE("gather methods are named camera[+vrl] and parse back") {
  for (vrlis::VrlChoice one : vrlis::kVrlSamplers)
    for (vrlis::SegmentChoice two : vrlis::kSegmentSamplers) {
      vrlis::GatherSamplers m{two, one};
      auto parsed = vrlis::ParseGatherSamplers(vrlis::Name(m));
      REQUIRE(parsed);
      CHECK(*parsed == m);
    }
  CHECK(vrlis::Name(*vrlis::ParseGatherSamplers("novak")) == "novak");
  CHECK(vrlis::Name(*vrlis::ParseGatherSamplers("full-product+marginal")) == "full-product+marginal");
  CHECK_FALSE(vrlis::ParseGatherSamplers("novak+"));
  CHECK_FALSE(vrlis::ParseGatherSamplers("nvak"));
  CHECK_FALSE(vrlis::ParseGatherSamplers("novak+novak"));
  CHECK_FALSE(vrlis::ParseGatherSamplers(""));
}

TEST_CASE("Medium's factories name the coefficients and reject a misfill by name") {
  using E = vrlis::QueryError;
  using M = vrlis::Medium<float>;
  const M absorbing = M::FromAbsorptionScattering(0.5f, 0.1f, 0.3f);
  CHECK(absorbing.g == 0.5f);
  CHECK(absorbing.sigma_s == 0.3f);
  CHECK(absorbing.sigma_t == 0.1f + 0.3f);
  const M extinct = M::FromScatteringExtinction(0.5f, 0.3f, 0.4f);
  CHECK((extinct.g == 0.5f && extinct.sigma_s == 0.3f && extinct.sigma_t == 0.4f));
  CHECK(vrlis::Validate(absorbing) == E::None);
  // sigma_s and sigma_t swapped, and a negative absorption: scattering above extinction.
  CHECK(vrlis::Validate(M::FromScatteringExtinction(0.5f, 0.4f, 0.3f)) == E::ScatteringExceedsExtinction);
  CHECK(vrlis::Validate(M::FromAbsorptionScattering(0.5f, -0.1f, 0.3f)) == E::ScatteringExceedsExtinction);
  CHECK(vrlis::Validate(M::FromAbsorptionScattering(0.5f, 0.5f, -0.3f)) == E::NegativeScattering);
  CHECK(std::string(vrlis::Describe(E::ScatteringExceedsExtinction)).find("sigma_a + sigma_s") != std::string::npos);
}
