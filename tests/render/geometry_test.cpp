// The scenes' ray casts against analytic answers: the cube scene's three spheres (positions
// from docs/scenes.md) met from outside, left from inside, and not met again by a ray that
// starts on one; occlusion agreeing with the closest hit.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include <vrlis_scenes/scenes.hpp>

namespace {

struct Ball {
  vrlis::integration::Vec3f center;
  double radius;
};
const Ball kCubeSpheres[] = {
    {{-0.75f, -1.45f, -4.4f}, 1.05}, {{2.0f, -2.05f, -3.7f}, 0.5}, {{-1.75f, -1.95f, -3.1f}, 0.6}};

// Entry distance of the ray o + t d (d unit) into the ball, in double; infinity if it misses
// or starts inside.
double Entry(const Ball& b, vrlis::integration::Vec3f o, vrlis::integration::Vec3f d) {
  double f[3] = {double(o.x) - b.center.x, double(o.y) - b.center.y, double(o.z) - b.center.z};
  double fd = f[0] * d.x + f[1] * d.y + f[2] * d.z, ff = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
  double disc = fd * fd - (ff - b.radius * b.radius);
  if (ff < b.radius * b.radius || disc < 0) return INFINITY;
  double t = -fd - std::sqrt(disc);
  return t > 0 ? t : INFINITY;
}

bool Inside(const Ball& b, vrlis::integration::Vec3f p) { return vrlis::integration::Length(p - b.center) < b.radius; }

vrlis::integration::Vec3f UniformDirection(std::mt19937& rng) {
  std::normal_distribution<float> n;
  return vrlis::integration::Normalize(vrlis::integration::Vec3f{n(rng), n(rng), n(rng)});
}

}  // namespace

TEST_CASE("cube: rays meet the spheres where the analytic spheres are", "[render][geometry]") {
  auto built = vrlis::scenes::BuildScene("cube", {});
  REQUIRE(built);
  const vrlis::integration::Geometry& g = *built->scene.geometry;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> x(-2.7f, 2.7f), y(-2.45f, 2.95f), z(-5.45f, 0.45f), u(0, 1);
  int aimed = 0;
  for (const Ball& target : kCubeSpheres) {
    for (int i = 0; i < 2000; ++i) {
      vrlis::integration::Vec3f o{x(rng), y(rng), z(rng)};
      bool inside = false;
      for (const Ball& b : kCubeSpheres) inside = inside || Inside(b, o);
      if (inside) continue;
      // Aim at a point inside the target and above the floor (two spheres sink into it): the
      // first surface met is a sphere, never a wall.
      vrlis::integration::Vec3f aim = target.center + float(0.99 * target.radius * std::cbrt(u(rng))) * UniformDirection(rng);
      if (aim.y < -2.45f) continue;
      vrlis::integration::Ray ray{o, vrlis::integration::Normalize(aim - o)};
      double t_ref = INFINITY;
      const Ball* first = nullptr;
      for (const Ball& b : kCubeSpheres) {
        double t = Entry(b, ray.o, ray.d);
        if (t < t_ref) t_ref = t, first = &b;
      }
      REQUIRE(first);
      vrlis::integration::SurfaceHit hit;
      REQUIRE(g.Intersect(ray, vrlis::integration::kInfinity, &hit));
      INFO("ray from " << o.x << ", " << o.y << ", " << o.z << " towards " << aim.x << ", " << aim.y << ", " << aim.z);
      CHECK(hit.t == Approx(t_ref).epsilon(1e-4));
      vrlis::integration::Vec3f n_ref = vrlis::integration::Normalize(ray(float(t_ref)) - first->center);
      CHECK(vrlis::integration::Dot(hit.n, n_ref) > 0.9999f);
      // Occlusion agrees: the segment stops short of the sphere or passes into it.
      CHECK_FALSE(g.Occluded(o, ray(float(t_ref) - 1e-3f)));
      CHECK(g.Occluded(o, ray(float(t_ref) + 1e-3f)));
      ++aimed;
    }
  }
  CHECK(aimed > 5000);
}

TEST_CASE("cube: a ray leaves a sphere it starts in or on, and only once", "[render][geometry]") {
  auto built = vrlis::scenes::BuildScene("cube", {});
  REQUIRE(built);
  const vrlis::integration::Geometry& g = *built->scene.geometry;
  std::mt19937 rng(8);
  for (const Ball& b : kCubeSpheres) {
    for (int i = 0; i < 1000; ++i) {
      vrlis::integration::Vec3f d = UniformDirection(rng);
      if (d.y < -0.3f) continue;  // the floor cuts two of the spheres
      // From the centre: the exit, with the outward normal, at the radius.
      vrlis::integration::SurfaceHit hit;
      REQUIRE(g.Intersect({b.center, d}, vrlis::integration::kInfinity, &hit));
      CHECK(hit.t == Approx(b.radius).epsilon(1e-5));
      CHECK(vrlis::integration::Dot(hit.n, d) > 0.9999f);
      // From that exit point, onwards: not the same sphere again (every other surface is at
      // least 0.05 away), and no occlusion up to halfway to the next surface.
      vrlis::integration::SurfaceHit next;
      REQUIRE(g.Intersect({hit.p, d}, vrlis::integration::kInfinity, &next));
      CHECK(next.t > 0.01f);
      CHECK_FALSE(g.Occluded(hit.p, hit.p + (0.5f * next.t) * d));
    }
  }
}
