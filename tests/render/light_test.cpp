// The lights' and media's geometry against brute force: the part of a ray inside a
// collimated beam against the beam's own Source test, a sphere medium's interval against its
// Contains test, and a spot light's light paths inside its cone carrying its power.
#include <catch2/catch.hpp>

#include <random>

#include <vrlis_integration/light_paths.hpp>
#include <vrlis_scenes/scenes.hpp>

namespace {

using vrlis::integration::Ray;
using vrlis::integration::Vec3f;

Vec3f RandomDirection(std::mt19937_64& rng) {
  std::normal_distribution<float> n;
  return vrlis::integration::Normalize(Vec3f{n(rng), n(rng), n(rng)});
}

// Where along [0, tmax] `inside` holds, by dense stepping: the first and last step inside.
template <typename Inside>
std::pair<float, float> Stepped(Inside inside, float tmax, int steps) {
  float lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i <= steps; ++i) {
    float t = tmax * i / steps;
    if (inside(t)) lo = std::min(lo, t), hi = std::max(hi, t);
  }
  return {lo, hi};
}

}  // namespace

TEST_CASE("a ray's part inside a collimated beam is where the beam has a source", "[render][lights]") {
  auto built = vrlis::scenes::BuildScene("fog", {});
  REQUIRE(built);
  const vrlis::integration::CollimatedRect& beam = built->scene.lights.rects.at(0);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<float> u(-1, 1);
  const float tmax = 12, step = tmax / 20000;
  int crossing = 0;
  for (int i = 0; i < 300; ++i) {
    Ray ray{Vec3f{2 * u(rng), 2 * u(rng), -2 + 2 * u(rng)}, RandomDirection(rng)};
    auto [a, b] = beam.Clip(ray, 0, tmax);
    auto [lo, hi] = Stepped([&](float t) { return beam.Source(ray(t)).has_value(); }, tmax, 20000);
    if (lo > hi) {
      CHECK(b - a < 2 * step);
      continue;
    }
    ++crossing;
    INFO("ray " << i << ": clip [" << a << ", " << b << "], stepped [" << lo << ", " << hi << "]");
    CHECK(std::abs(a - lo) < 2 * step);
    CHECK(std::abs(b - hi) < 2 * step);
  }
  CHECK(crossing > 30);  // the rays do test the beam
}

TEST_CASE("a sphere medium's interval is where it contains the ray", "[render][lights]") {
  auto built = vrlis::scenes::BuildScene("cloud", {});
  REQUIRE(built);
  const vrlis::integration::HomogeneousMedium& m = built->scene.medium;
  REQUIRE(m.shape == vrlis::integration::HomogeneousMedium::Shape::Sphere);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<float> u(-1, 1);
  const float tmax = 8, step = tmax / 20000;
  int crossing = 0;
  for (int i = 0; i < 300; ++i) {
    Ray ray{m.center + Vec3f{2 * u(rng), 2 * u(rng), 2 * u(rng)}, RandomDirection(rng)};
    vrlis::integration::Interval iv = m.Clip(ray, tmax);
    auto [lo, hi] = Stepped([&](float t) { return m.Contains(ray(t)); }, tmax, 20000);
    if (lo > hi) {
      CHECK(iv.Length() < 2 * step);
      continue;
    }
    ++crossing;
    CHECK(std::abs(iv.a - lo) < 2 * step);
    CHECK(std::abs(iv.b - hi) < 2 * step);
  }
  CHECK(crossing > 30);
}

TEST_CASE("a spot light's light paths leave inside its cone and carry its power", "[render][lights]") {
  auto built = vrlis::scenes::BuildScene("cloud", {});
  REQUIRE(built);
  const vrlis::integration::Scene& scene = built->scene;
  const vrlis::integration::PointLight& spot = scene.lights.points.at(0);
  REQUIRE(spot.cos_cone > -1);
  CHECK(scene.lights.Powers().at(0) == Approx(spot.SolidAngle() * spot.intensity.Average()));
  vrlis::integration::TransportSettings first;
  first.max_depth = 1;  // the light's own segments only, before any bounce
  int outside = 0, total = 0;
  for (std::uint64_t pass = 0; pass < 50; ++pass)
    for (const vrlis::integration::Vrl& v : vrlis::integration::TraceLightPaths(scene, first, 256, 9, pass)) {
      ++total;
      if (vrlis::integration::Dot(v.dir, spot.axis) < spot.cos_cone - 1e-6f) ++outside;
      // The first segments start where the light paths enter the cloud, straight from the spot.
      CHECK(v.flux.r == Approx(spot.SolidAngle() * spot.intensity.r / 256));
    }
  CHECK(total > 1000);
  CHECK(outside == 0);
}
