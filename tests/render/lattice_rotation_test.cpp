// The bidirectional scene's light turns its Fibonacci lattice by a uniformly random rotation
// per pass: the rotation is proper, every beam is uniform on the sphere over passes, and the
// image converges to the point light's double scattering (the VRL integral averaged over all
// light directions), whatever the number of beams.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>

#include <vrlis_integration/light_paths.hpp>
#include <vrlis_scenes/scenes.hpp>

#include "block_stats.hpp"
#include "stats.hpp"  // tests/support: Pearson's chi-square
#include "uncontrolled.hpp"

namespace {

using vrlis::integration::Rotation;
using vrlis::integration::Vec3f;

double Det(const Rotation& r) { return Dot(r.row[0], Cross(r.row[1], r.row[2])); }

// Largest deviation of R R^T from the identity, and of det R from +1.
double ProperRotationError(const Rotation& r) {
  double e = std::abs(Det(r) - 1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) e = std::max(e, std::abs(double(Dot(r.row[i], r.row[j])) - (i == j)));
  return e;
}

// Pearson's test of directions against the uniform density on the sphere, over 8 x 8
// equal-area bins in z = cos theta and phi.
vrlis::test::ChiSquare UniformOnSphere(const std::vector<Vec3f>& directions) {
  const int nz = 8, nphi = 8;
  std::vector<long> counts(nz * nphi, 0);
  for (Vec3f d : directions) {
    int iz = std::clamp(static_cast<int>((d.z + 1) / 2 * nz), 0, nz - 1);
    double phi = std::atan2(double(d.y), double(d.x)) + M_PI;
    int iphi = std::clamp(static_cast<int>(phi / (2 * M_PI) * nphi), 0, nphi - 1);
    ++counts[static_cast<std::size_t>(iz * nphi + iphi)];
  }
  return vrlis::test::PearsonTest(counts, std::vector<double>(counts.size(), 1.0), static_cast<long>(directions.size()));
}

// Beam `beam` of `count` in each of `passes` passes, as the light pass traces it.
std::vector<Vec3f> BeamDirections(const vrlis::scenes::BuiltScene& built, int beam, int count, int passes) {
  std::vector<Vec3f> d;
  for (int p = 0; p < passes; ++p) {
    std::vector<vrlis::integration::Vrl> vrls =
        vrlis::integration::TraceLightPaths(built.scene, built.transport, count, 3, static_cast<std::uint64_t>(p));
    d.push_back(vrls.at(static_cast<std::size_t>(beam)).dir);
  }
  return d;
}

}  // namespace

TEST_CASE("bidirectional: the lattice's rotation is proper and every beam uniform on the sphere", "[render][lattice]") {
  auto built = vrlis::scenes::BuildScene("bidirectional", {});
  REQUIRE(built);
  const vrlis::integration::PointLight& light = built->scene.lights.points.at(0);
  REQUIRE(light.fibonacci_beams);
  REQUIRE(light.rotate_lattice);

  double worst = 0;
  for (std::uint64_t p = 0; p < 1000; ++p) worst = std::max(worst, ProperRotationError(vrlis::integration::LatticeRotation(light, 3, p, 0)));
  std::printf("[render] lattice rotation: max |R R^T - I|, |det R - 1| over 1000 passes %.2g\n", worst);
  CHECK(worst < 1e-5);
  Rotation reflection = vrlis::integration::LatticeRotation(light, 3, 0, 0);
  reflection.row[2] = -reflection.row[2];
  CHECK(ProperRotationError(reflection) > 1);  // the check sees a reflection

  const int count = 8, beam = 3, passes = 6400;
  std::vector<Vec3f> rotated = BeamDirections(*built, beam, count, passes);
  for (int p = 0; p < 4; ++p) {  // the light pass uses exactly this pass's rotation
    Vec3f expected = vrlis::integration::LatticeRotation(light, 3, static_cast<std::uint64_t>(p), 0)(
        vrlis::integration::FibonacciDirection(beam, count));
    CHECK(Length(rotated[static_cast<std::size_t>(p)] - expected) < 1e-5f);
  }
  vrlis::test::ChiSquare chi = UniformOnSphere(rotated);
  std::printf("[render] lattice rotation: beam %d of %d over %d passes, chi2 %.1f (dof %d), p %.3g\n", beam, count,
              passes, chi.statistic, chi.dof, chi.p_value);
  CHECK(chi.Passes());

  // Controls the test must reject: the fixed lattice, and turns about the z axis only.
  built->scene.lights.points.at(0).rotate_lattice = false;
  CHECK_FALSE(UniformOnSphere(BeamDirections(*built, beam, count, passes)).Passes());
  std::vector<Vec3f> about_z;
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<float> angle(0, 2 * vrlis::integration::kPi);
  const Vec3f f = vrlis::integration::FibonacciDirection(beam, count);
  for (int p = 0; p < passes; ++p) {
    float a = angle(gen);
    about_z.push_back({std::cos(a) * f.x - std::sin(a) * f.y, std::sin(a) * f.x + std::cos(a) * f.y, f.z});
  }
  vrlis::test::ChiSquare chi_z = UniformOnSphere(about_z);
  std::printf("[render] lattice rotation control, turns about z: chi2 %.1f (dof %d), p %.3g\n", chi_z.statistic,
              chi_z.dof, chi_z.p_value);
  CHECK_FALSE(chi_z.Passes());
}

// The point light's double scattering seen along a camera ray (o, wc) of length L: with N
// beams of flux 4 pi I / N, each uniform on the sphere, a pixel's expected value is
// I Int_{S^2} VrlIntegral(w) dw (the VRL integral of section 1 of
// docs/maths.md#medium-to-medium, VRLs of length L). With y = x_l + v w, d^3y = v^2 dv dw, it
// is the volume integral
//   I sigma_s^2 Int_0^L du Int_{|y - x_l| < L} d^3y rho(wc . w^) rho(-w_l . w^) T(u + v + r) / (v^2 r^2),
// x = o + u wc, r = |y - x|, w^ = (y - x) / r, v = |y - x_l|, w_l = (y - x_l) / v. Monte Carlo:
// u by its transmittance, y by a mixture of a distance-sampled sphere about x and one about
// x_l, which cancels both 1 / r^2 and 1 / v^2: the weight is bounded while the camera ray
// keeps away from the light, so the standard error is a sound one.
struct Estimate {
  double mean, se;
};

Estimate DoubleScattering(const vrlis::integration::Scene& scene, const vrlis::integration::Ray& ray, long samples,
                          std::uint64_t seed) {
  using vrlis::test::V3;
  const vrlis::integration::HomogeneousMedium& m = scene.medium;
  const vrlis::integration::PointLight& light = scene.lights.points.at(0);
  const double st = m.SigmaT(), L = m.max_distance, kept = 1 - std::exp(-st * L);
  const V3 o{ray.o.x, ray.o.y, ray.o.z}, wc{ray.d.x, ray.d.y, ray.d.z};
  const V3 xl{light.position.x, light.position.y, light.position.z};
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  vrlis::RunningMoments acc;
  for (long i = 0; i < samples; ++i) {
    double u = -std::log(1 - unit(gen) * kept) / st;
    V3 x = o + u * wc, w = vrlis::test::RandomUnit(gen);
    V3 y = unit(gen) < 0.5 ? x + (-std::log(1 - unit(gen)) / st) * w : xl + (-std::log(1 - unit(gen) * kept) / st) * w;
    double r = vrlis::test::Norm(y - x), v = vrlis::test::Norm(y - xl);
    double pu = st * std::exp(-st * u) / kept;
    double py = 0.5 * st * std::exp(-st * r) / (4 * M_PI * r * r) +
                (v < L ? 0.5 * st * std::exp(-st * v) / (kept * 4 * M_PI * v * v) : 0);
    double f = 0;
    if (v < L) {
      V3 wh = (1 / r) * (y - x), wl = (1 / v) * (y - xl);
      f = light.intensity.r * m.sigma_s * m.sigma_s * vrlis::test::HgBetween(m.g, wc, wh) *
          vrlis::test::HgBetween(m.g, -1.0 * wl, wh) * std::exp(-st * (u + v + r)) / (v * v * r * r);
    }
    acc.add(f / (pu * py));
  }
  return {acc.mean(), acc.standard_error()};
}

TEST_CASE("bidirectional: the rotated lattice converges to the point light's double scattering", "[render][reference]") {
  auto built = vrlis::scenes::BuildScene("bidirectional", {});
  REQUIRE(built);
  const vrlis::integration::Scene& scene = built->scene;
  vrlis::integration::RenderSettings s;
  s.width = s.height = 16;
  s.vrls_per_pass = 16;
  s.jitter = false;
  s.transport = vrlis::test::Uncontrolled(built->transport);
  const int passes = 4096;
  std::vector<std::pair<int, int>> pixels;
  for (int y = 1; y < 16; y += 3)
    for (int x = 1; x < 16; x += 3) pixels.push_back({x, y});

  std::vector<double> ref, ref_se;
  for (auto [px, py] : pixels) {
    Estimate e = DoubleScattering(scene, scene.camera.Generate(px + 0.5f, py + 0.5f, s.width, s.height), 1 << 19,
                                  static_cast<std::uint64_t>(py * s.width + px));
    ref.push_back(e.mean);
    ref_se.push_back(e.se);
  }

  vrlis::integration::VrlRenderer renderer(scene, s);
  std::vector<vrlis::RunningMoments> stats(pixels.size());
  for (int p = 0; p < passes; ++p) {
    vrlis::integration::Film f = renderer.RenderPass(9, static_cast<std::uint64_t>(p), nullptr);
    for (std::size_t k = 0; k < pixels.size(); ++k) stats[k].add(f.at(pixels[k].first, pixels[k].second).r);
  }
  auto [mean, se] = vrlis::test::Estimates(stats);
  for (std::size_t k = 0; k < pixels.size(); ++k)
    std::printf("[render] rotated lattice, pixel (%d, %d): render %.5g +- %.2g, reference %.5g +- %.2g\n",
                pixels[k].first, pixels[k].second, mean[k], se[k], ref[k], ref_se[k]);
  auto z = vrlis::test::Compare(mean, se, ref, ref_se);
  std::printf("[render] rotated lattice vs the double scattering: %s\n", z.Describe().c_str());
  CHECK(z.Pass());
  for (double& r : ref) r *= 1.1;  // negative control: 10% off must be detected
  auto zc = vrlis::test::Compare(mean, se, ref, ref_se);
  std::printf("[render] rotated lattice, control x1.10: %s\n", zc.Describe().c_str());
  CHECK_FALSE(zc.Pass());
}
