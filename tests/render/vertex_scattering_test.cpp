// Single scattering of a point light seen from a scattering vertex, sampled jointly
// (VertexSingleScattering, docs/maths.md#two-point): its mean against nested quadrature of
// the same integral over the directions leaving the vertex and the distance along them, in an
// unbounded medium, for a phase-function vertex and a surface vertex; and its weights bounded
// by the pi^3 / D the joint density promises.
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <catch2/catch.hpp>

#include <vrlis_integration/gather.hpp>
#include <vrlis_scenes/scenes.hpp>

#include "integrand.hpp"  // tests/support: vectors in double, Henyey-Greenstein

namespace {

using vrlis::integration::Vec3f;
using vrlis::test::Cross;
using vrlis::test::Dot;
using vrlis::test::HgBetween;
using vrlis::test::Unit;
using vrlis::test::V3;
V3 D(Vec3f v) { return vrlis::test::FromVec(v); }

// I Int_S2 lobe(w) Int_0^L sigma_s rho(w . u^) T(t) T(r) / r^2 dt dw, u the unit vector from
// p + t w to the light and r its length, in coordinates about the axis p -> light: w at angle
// alpha and azimuth phi, t = t0 + h tan(theta), so that dw dt / r^2 = dalpha dphi dtheta / D.
template <typename Lobe>
double Reference(V3 p, V3 light, double L, double sigma_s, double sigma_t, double g, Lobe lobe) {
  using Quad = boost::math::quadrature::gauss_kronrod<double, 21>;
  V3 d = light - p;
  const double dist = std::sqrt(Dot(d, d));
  const V3 axis = (1 / dist) * d;
  const V3 x = Unit(Cross(axis, std::abs(axis.x) < 0.9 ? V3{1, 0, 0} : V3{0, 1, 0})), y = Cross(axis, x);
  auto over_alpha = [&](double alpha) {
    const double t0 = dist * std::cos(alpha), h = dist * std::sin(alpha);
    auto over_phi = [&](double phi) {
      V3 w = (std::sin(alpha) * std::cos(phi)) * x + (std::sin(alpha) * std::sin(phi)) * y + std::cos(alpha) * axis;
      double f = lobe(w);
      if (!(f > 0)) return 0.0;
      auto over_theta = [&](double theta) {
        double t = t0 + h * std::tan(theta), r = h / std::cos(theta);
        V3 u = (1 / r) * (light - (p + t * w));
        return sigma_s * HgBetween(g, w, u) * std::exp(-sigma_t * (t + r));
      };
      return f * Quad::integrate(over_theta, std::atan(-t0 / h), std::atan((L - t0) / h), 10, 1e-8);
    };
    return Quad::integrate(over_phi, 0, 2 * M_PI, 10, 1e-7);
  };
  return Quad::integrate(over_alpha, 1e-7, M_PI - 1e-7, 10, 1e-6) / dist;
}

}  // namespace

TEST_CASE("vertex single scattering matches quadrature and its weights stay bounded", "[render][reference]") {
  auto built = vrlis::scenes::BuildScene("bidirectional", {});  // unbounded medium, no surfaces
  REQUIRE(built);
  vrlis::integration::Scene scene = built->scene;
  scene.medium.g = 0.6f;
  const Vec3f light{0, 0, -2}, p{0.7f, -0.4f, -1.2f};
  const float intensity = 2;
  scene.lights.points = {{light, vrlis::integration::Spectrum(intensity), false}};
  const vrlis::integration::HomogeneousMedium& m = scene.medium;
  const double dist = std::sqrt(Dot(D(light - p), D(light - p)));

  const Vec3f into = vrlis::integration::Normalize(Vec3f{0.2f, 0.9f, -0.3f});
  const Vec3f normal = vrlis::integration::Normalize(Vec3f{-0.6f, 0.1f, -0.5f});
  struct Case {
    const char* name;
    vrlis::integration::VertexLobe lobe;
    double lobe_max;
  };
  const Case cases[] = {{"medium vertex", {into, -0.5f, false}, HgBetween(-0.5, D(into), -1.0 * D(into))},
                        {"surface vertex", {normal, 0, true}, 1 / M_PI}};
  for (const Case& c : cases) {
    SECTION(c.name) {
      auto lobe = [&](V3 w) { return c.lobe.cosine ? std::max(0.0, Dot(D(c.lobe.axis), w)) / M_PI
                                                   : HgBetween(c.lobe.g, D(c.lobe.axis), w); };
      const double ref = intensity * Reference(D(p), D(light), m.max_distance, m.sigma_s, m.SigmaT(), m.g, lobe);
      vrlis::integration::Rng rng(5, 0, 0, vrlis::integration::StreamPurpose::Camera);
      const int n = 400000;
      double sum = 0, sum2 = 0, largest = 0;
      for (int i = 0; i < n; ++i) {
        double v = vrlis::integration::VertexSingleScattering(scene, p, c.lobe, rng).r;
        sum += v;
        sum2 += v * v;
        largest = std::max(largest, v);
      }
      const double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1));
      INFO("mean " << mean << " +- " << se << ", quadrature " << ref << ", largest weight " << largest);
      CHECK(std::abs(mean - ref) < 4 * se);
      CHECK(std::abs(mean - 1.05 * ref) > 4 * se);  // the budget resolves a 5% error
      // pi^3 / D times the largest of the other factors (transmittance at most 1).
      const double phase_max = HgBetween(m.g, D(into), D(into));  // m.g > 0: forward
      CHECK(largest <= intensity * m.sigma_s * phase_max * c.lobe_max * M_PI * M_PI * M_PI / dist * 1.001);
    }
  }
}
