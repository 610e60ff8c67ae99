// The noise-free accuracy study (bench/study/variance.hpp) against Monte Carlo: the first
// and second moments of the estimator computed by quadrature must match those of seeded
// Monte Carlo runs of the real samplers (sample() and pdf() in the segment parameter, not
// the angle-domain shortcut the quadrature takes) within 5 standard errors; a mismatched
// pairing must be rejected, so the comparison is shown to have teeth; and the quadrature
// must be converged (refining the tolerances changes nothing that matters).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>

#include "study/variance.hpp"

namespace {

using namespace vrlis;
using namespace vrlis::study;

struct McMoments {
  double mean = 0, second = 0;        // of X and of X^2
  double se_mean = 0, se_second = 0;  // their standard errors
};

// X = f / p for n seeded samples of `draw`, which returns {f, p}.
McMoments RunMc(std::uint64_t seed, int n, const std::function<std::pair<double, double>(Rng&)>& draw) {
  Rng rng(seed);
  double s1 = 0, s2 = 0, s4 = 0;
  for (int i = 0; i < n; ++i) {
    auto [f, p] = draw(rng);
    double x = p > 0 ? f / p : 0;
    double x2 = x * x;
    s1 += x;
    s2 += x2;
    s4 += x2 * x2;
  }
  McMoments m;
  m.mean = s1 / n;
  m.second = s2 / n;
  m.se_mean = std::sqrt(std::max(m.second - m.mean * m.mean, 0.0) / n);
  m.se_second = std::sqrt(std::max(s4 / n - m.second * m.second, 0.0) / n);
  return m;
}

// The k-th camera sampler of SamplerTuple in double: a sample u and its density p(u).
template <size_t... I>
std::pair<double, double> SampleCameraImpl(int k, const SegmentQuery<double>& q, double xi, std::index_sequence<I...>) {
  std::pair<double, double> out{0, 0};
  auto run = [&](const auto& sampler) {
    double u = sampler.sample(xi);
    out = {u, sampler.pdf(u)};
  };
  ((k == int(I) ? run(std::tuple_element_t<I, SamplerTuple<double>>(q)) : void()), ...);
  return out;
}

std::pair<double, double> SampleCamera(int k, const SegmentQuery<double>& q, double xi) {
  return SampleCameraImpl(k, q, xi, std::make_index_sequence<kCameraSamplerCount>());
}

McMoments WholeMc(const Pair<double>& p, int k, int n, std::uint64_t seed) {
  VrlPoint<double> vp(VrlQuery(p));
  return RunMc(seed, n, [&](Rng& rng) {
    double v = vp.sample(rng.uniform()), p1 = vp.pdf(v);
    Vec3<double> y = VrlPointAt(p, v);
    auto [u, p2] = SampleCamera(k, CameraQuery(p, y), rng.uniform());
    return std::pair{IntegrandAt(p, u, y, v), p1 * p2};
  });
}

McMoments CameraMc(const Pair<double>& p, int k, int n, std::uint64_t seed) {
  VrlPoint<double> vp(VrlQuery(p));
  double v = vp.sample(p.xi_vrl);
  Vec3<double> y = VrlPointAt(p, v);
  SegmentQuery<double> q = CameraQuery(p, y);
  return RunMc(seed, n, [&](Rng& rng) {
    auto [u, pdf] = SampleCamera(k, q, rng.uniform());
    return std::pair{IntegrandAt(p, u, y, v), pdf};
  });
}

double Z(double estimate, double se, double exact) { return std::abs(estimate - exact) / std::max(se, 1e-300); }

}  // namespace

TEST_CASE("quadrature of the relative variance matches Monte Carlo", "[accuracy]") {
  const int n = 120000;
  int checked = 0;
  for (double g : {-0.5, 0.7, 0.9}) {
    auto pairs = MakePairs(kDefaultSeed, 2, g);
    for (size_t pi = 0; pi < pairs.size(); ++pi) {
      const Pair<double>& p = pairs[pi];
      Moments whole = WholeMoments(p), camera = CameraStepMoments(p);
      REQUIRE(whole.converged);
      REQUIRE(camera.converged);
      for (int k = 0; k < kCameraSamplerCount; ++k) {
        std::uint64_t seed = 1000 * pi + 10 * k + std::uint64_t(100 * (g + 1));
        McMoments w = WholeMc(p, k, n, seed), c = CameraMc(p, k, n, seed + 7);
        INFO("g = " << g << ", pair " << pi << ", " << kCameraSamplerNames[k]);
        INFO("whole: relvar quadrature " << whole.RelativeVariance(k) << ", Monte Carlo "
                                         << w.second / (w.mean * w.mean) - 1);
        INFO("camera: relvar quadrature " << camera.RelativeVariance(k) << ", Monte Carlo "
                                          << c.second / (c.mean * c.mean) - 1);
        // The Monte Carlo runs are precise enough that a 10% error in the second moment
        // would stand out by several standard errors.
        CHECK(w.se_second < 0.02 * w.second);
        CHECK(c.se_second < 0.02 * c.second);
        CHECK(Z(w.mean, w.se_mean, whole.first) < 5);
        CHECK(Z(w.second, w.se_second, whole.second[k]) < 5);
        CHECK(Z(c.mean, c.se_mean, camera.first) < 5);
        CHECK(Z(c.second, c.se_second, camera.second[k]) < 5);
        ++checked;
      }
    }
  }
  CHECK(checked == 3 * 2 * kCameraSamplerCount);
}

TEST_CASE("the Monte Carlo comparison rejects a mismatched sampler", "[accuracy]") {
  // Quadrature for Novák against Monte Carlo of equiangular sampling (and back): the
  // relative variances differ several-fold at g = 0.9, so the check must fail.
  Pair<double> p = MakePairs(kDefaultSeed, 1, 0.9)[0];
  Moments camera = CameraStepMoments(p), whole = WholeMoments(p);
  REQUIRE(camera.RelativeVariance(0) > 2 * camera.RelativeVariance(1));
  McMoments c_eq = CameraMc(p, 0, 200000, 1), w_eq = WholeMc(p, 0, 200000, 2);
  McMoments c_nv = CameraMc(p, 1, 200000, 3);
  CHECK(Z(c_eq.second, c_eq.se_second, camera.second[1]) > 5);
  CHECK(Z(c_nv.second, c_nv.se_second, camera.second[0]) > 5);
  CHECK(Z(w_eq.second, w_eq.se_second, whole.second[1]) > 5);
  // A density off by a constant factor is caught through the first moment.
  CHECK(Z(1.1 * w_eq.mean, 1.1 * w_eq.se_mean, whole.first) > 5);
}

TEST_CASE("the quadrature is converged at g = +-0.99", "[accuracy]") {
  QuadratureSettings fine;
  fine.inner_tol = 1e-11;
  fine.outer_tol = 1e-9;
  fine.inner_max = 400000;
  fine.outer_max = 40000;
  for (double g : {-0.99, 0.99}) {
    for (const Pair<double>& p : MakePairs(kDefaultSeed, 4, g)) {
      Moments a = WholeMoments(p), b = WholeMoments(p, fine);
      Moments ca = CameraStepMoments(p), cb = CameraStepMoments(p, fine);
      REQUIRE(a.converged);
      REQUIRE(b.converged);
      for (int k = 0; k < kCameraSamplerCount; ++k) {
        INFO("g = " << g << ", " << kCameraSamplerNames[k]);
        CHECK(a.RelativeVariance(k) == Approx(b.RelativeVariance(k)).epsilon(1e-4));
        CHECK(ca.RelativeVariance(k) == Approx(cb.RelativeVariance(k)).epsilon(1e-6).margin(1e-12));
        // The central form agrees with second / first^2 - 1 (which loses digits near 0).
        CHECK(ca.RelativeVariance(k) == Approx(ca.second[k] / (ca.first * ca.first) - 1).margin(1e-7));
      }
    }
  }
}

TEST_CASE("at g = 0 every phase-only camera sampler is equiangular", "[accuracy]") {
  // Novák and both Cauchy samplers follow the phase product only; FullProduct also follows
  // transmittance, so with sigma_t = 1 it must do better than equiangular sampling here.
  for (const Pair<double>& p : MakePairs(kDefaultSeed, 4, 0.0)) {
    Moments m = WholeMoments(p);
    for (int k = 1; k <= 3; ++k) CHECK(m.RelativeVariance(k) == Approx(m.RelativeVariance(0)).epsilon(1e-6));
    CHECK(std::string(kCameraSamplerNames[4]) == "FullProduct");
    CHECK(m.RelativeVariance(4) < m.RelativeVariance(0));
  }
}
