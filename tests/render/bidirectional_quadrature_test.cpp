// The bidirectional scene with its lattice fixed: its light emits only along fixed
// directions, which no path tracer can connect to, so the reference is the VRL integral
// itself (section 1 of the docs/maths.md#medium-to-medium), integrated numerically per pixel
// (pixel centres) with nested adaptive Gauss-Kronrod quadrature. Every sampler is checked, and
// FullProduct after VrlMarginal, whose fits go to the gathers the earlier passes' scores put
// first (TransportSettings::marginal_fraction): per-pixel z-scores over independent passes,
// Bonferroni over all pixels and samplers.
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <catch2/catch.hpp>

#include <cstdio>

#include <vrlis_scenes/scenes.hpp>

#include "block_stats.hpp"
#include "uncontrolled.hpp"

namespace {

using vrlis::integration::Vec3f;

struct V3 {
  double x, y, z;
};
V3 D(Vec3f v) { return {v.x, v.y, v.z}; }
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
double Dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

double Hg(double g, double cos) { return (1 - g * g) / (4 * M_PI * std::pow(1 + g * g - 2 * g * cos, 1.5)); }

// Phi sigma_s^2 Int_0^L Int_0^t rho(w_c . w^) rho(-w_l . w^) T(u) T(v) T(|w|) / |w|^2 dv du,
// the inner integral over the camera segment in the angle variable u - u0 = h tan(theta).
double VrlIntegral(V3 o, V3 wc, double L, V3 xl, V3 wl, double t, const vrlis::integration::HomogeneousMedium& m) {
  using Quad = boost::math::quadrature::gauss_kronrod<double, 31>;
  const double st = m.SigmaT(), g = m.g;
  auto inner = [&](double v) {
    V3 y = xl + v * wl, d = y - o;
    double u0 = Dot(d, wc);
    V3 perp = d - u0 * wc;
    double h = std::sqrt(Dot(perp, perp));
    double ta = std::atan(-u0 / h), tb = std::atan((L - u0) / h);
    auto f = [&](double theta) {
      double u = u0 + h * std::tan(theta), r = h / std::cos(theta);
      V3 w = (1 / r) * (y - (o + u * wc));
      return Hg(g, Dot(wc, w)) * Hg(g, -Dot(wl, w)) * std::exp(-st * (u + v + r)) / h;
    };
    return Quad::integrate(f, ta, tb, 12, 1e-9);
  };
  // Split the VRL at its point closest to the camera line, where the inner integral peaks.
  V3 d = o - xl;
  double c = Dot(wl, wc), denom = 1 - c * c;
  double vs = denom > 1e-12 ? (Dot(d, wl) - Dot(d, wc) * c) / denom : 0;
  vs = std::clamp(vs, 0.0, t);
  double sum = 0;
  if (vs > 0) sum += Quad::integrate(inner, 0.0, vs, 12, 1e-9);
  if (vs < t) sum += Quad::integrate(inner, vs, t, 12, 1e-9);
  return m.sigma_s * m.sigma_s * sum;
}

}  // namespace

TEST_CASE("bidirectional: every sampler matches the quadrature of the VRL integral", "[render][reference]") {
  auto built = vrlis::scenes::BuildScene("bidirectional", {});
  REQUIRE(built);
  built->scene.lights.points.at(0).rotate_lattice = false;  // the same N beams in every pass
  const vrlis::integration::Scene& scene = built->scene;
  vrlis::integration::RenderSettings s;
  s.width = s.height = 16;
  s.vrls_per_pass = 8;
  s.jitter = false;
  s.transport = vrlis::test::Uncontrolled(built->transport);
  const int passes = 512;
  const std::vector<std::pair<int, int>> pixels = {{2, 3}, {5, 8}, {7, 7}, {9, 4}, {11, 12}, {13, 6}, {4, 13}, {8, 10}};

  // The reference: the same VRLs the renderer traces (fixed directions, flux power / N).
  const vrlis::integration::PointLight& light = scene.lights.points.at(0);
  const double flux = 4 * M_PI * light.intensity.r / s.vrls_per_pass;
  const double L = scene.medium.max_distance;
  std::vector<double> ref;
  for (auto [px, py] : pixels) {
    vrlis::integration::Ray ray = scene.camera.Generate(px + 0.5f, py + 0.5f, s.width, s.height);
    double sum = 0;
    for (int i = 0; i < s.vrls_per_pass; ++i)
      sum += VrlIntegral(D(ray.o), D(ray.d), L, D(light.position), D(vrlis::integration::FibonacciDirection(i, s.vrls_per_pass)),
                         L, scene.medium);
    ref.push_back(flux * sum);
  }

  std::vector<vrlis::GatherSamplers> methods;
  for (vrlis::SegmentChoice segment : vrlis::kSegmentSamplers) methods.push_back({segment, {}});
  methods.push_back(*vrlis::ParseGatherSamplers("full-product+marginal"));
  REQUIRE(s.transport.marginal_fraction < 1);
  std::vector<double> mean_all, se_all, ref_all;
  for (vrlis::GatherSamplers method : methods) {
    s.transport.sampling = method;
    vrlis::integration::VrlRenderer renderer(scene, s);
    std::vector<vrlis::RunningMoments> stats(pixels.size());
    for (int p = 0; p < passes; ++p) {
      vrlis::integration::Film f = renderer.RenderPass(5, static_cast<std::uint64_t>(p), nullptr);
      for (std::size_t k = 0; k < pixels.size(); ++k) stats[k].add(f.at(pixels[k].first, pixels[k].second).r);
    }
    auto [mean, se] = vrlis::test::Estimates(stats);
    auto z = vrlis::test::Compare(mean, se, ref, std::vector<double>(ref.size(), 0.0), 0.01 / static_cast<double>(methods.size()));
    std::printf("[render] bidirectional, %s vs quadrature: %s\n", std::string(vrlis::Name(method)).c_str(),
                z.Describe().c_str());
    mean_all.insert(mean_all.end(), mean.begin(), mean.end());
    se_all.insert(se_all.end(), se.begin(), se.end());
    ref_all.insert(ref_all.end(), ref.begin(), ref.end());
  }
  // All samplers and pixels together, Bonferroni over all comparisons.
  auto z = vrlis::test::Compare(mean_all, se_all, ref_all, std::vector<double>(ref_all.size(), 0.0));
  std::printf("[render] bidirectional, all samplers: %s\n", z.Describe().c_str());
  CHECK(z.Pass());
  // Negative control: 10% off must be detected.
  for (double& r : ref_all) r *= 1.1;
  auto zc = vrlis::test::Compare(mean_all, se_all, ref_all, std::vector<double>(ref_all.size(), 0.0));
  std::printf("[render] bidirectional, control x1.10: %s\n", zc.Describe().c_str());
  CHECK_FALSE(zc.Pass());
}
