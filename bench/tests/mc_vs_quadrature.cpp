// The noise-free accuracy study (bench/study/variance.hpp) against Monte Carlo: the first
// and second moments of the estimator computed by quadrature must match those of seeded
// Monte Carlo runs of the real samplers (sample() and pdf() in the segment parameter, not
// the angle-domain shortcut the quadrature takes) within 5 standard errors; a mismatched
// pairing must be rejected, so the comparison is shown to have teeth; and the quadrature
// must be converged (refining the tolerances changes nothing that matters).
#include <catch2/catch.hpp>
#include <vrlis/core/running_moments.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
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
  RunningMoments x, x2;
  for (int i = 0; i < n; ++i) {
    auto [f, p] = draw(rng);
    double w = p > 0 ? f / p : 0;
    x.add(w);
    x2.add(w * w);
  }
  return {x.mean(), x2.mean(), x.standard_error(), x2.standard_error()};
}

// The k-th camera sampler of the registry in double: a sample u and its density p(u).
std::pair<double, double> SampleCamera(int k, const SegmentQuery<double>& q, double xi) {
  return SegmentSamplers::With(kSegmentSamplers[k], q, [&](const auto& sampler) {
    double u = sampler.sample(xi);
    return std::pair{u, sampler.pdf(u)};
  });
}

McMoments WholeMc(const MediumGatherQuery<double>& q, int k, int n, std::uint64_t seed) {
  VrlPoint<double> vp(q);
  return RunMc(seed, n, [&](Rng& rng) {
    double v = vp.sample(rng.uniform()), p1 = vp.pdf(v);
    auto [u, p2] = SampleCamera(k, CameraStepQuery(q, q.vrl.at(v)), rng.uniform());
    return std::pair{IntegrandAt(q, u, v), p1 * p2};
  });
}

McMoments CameraMc(const Config<double>& c, int k, int n, std::uint64_t seed) {
  VrlPoint<double> vp(c.query);
  double v = vp.sample(c.xi_vrl);
  SegmentQuery<double> q = CameraStepQuery(c.query, c.query.vrl.at(v));
  return RunMc(seed, n, [&](Rng& rng) {
    auto [u, pdf] = SampleCamera(k, q, rng.uniform());
    return std::pair{IntegrandAt(c.query, u, v), pdf};
  });
}

double Z(double estimate, double se, double exact) { return std::abs(estimate - exact) / std::max(se, 1e-300); }

}  // namespace

TEST_CASE("quadrature of the relative variance matches Monte Carlo", "[accuracy]") {
  const int n = 120000;
  int checked = 0;
  for (double g : {-0.5, 0.7, 0.9}) {
    auto configs = MakeConfigs(kDefaultSeed, 2, g);
    for (size_t pi = 0; pi < configs.size(); ++pi) {
      const Config<double>& p = configs[pi];
      Moments whole = WholeMoments(p.query), camera = CameraStepMoments(p.query, p.xi_vrl);
      REQUIRE(whole.converged);
      REQUIRE(camera.converged);
      for (int k = 0; k < kCameraSamplerCount; ++k) {
        std::uint64_t seed = 1000 * pi + 10 * k + std::uint64_t(100 * (g + 1));
        McMoments w = WholeMc(p.query, k, n, seed), c = CameraMc(p, k, n, seed + 7);
        INFO("g = " << g << ", configuration " << pi << ", " << Name(kSegmentSamplers[k]));
        INFO("whole: relvar quadrature " << whole.RelativeVariance(k) << ", Monte Carlo "
                                         << w.second / (w.mean * w.mean) - 1);
        INFO("camera: relvar quadrature " << camera.RelativeVariance(k) << ", Monte Carlo "
                                          << c.second / (c.mean * c.mean) - 1);
        // The Monte Carlo runs are precise enough that a 10% error in the second moment of
        // the camera step, and a 25% error in that of the whole estimator (heavy-tailed where
        // a long segment passes close to the VRL), would stand out by 5 standard errors.
        CHECK(w.se_second < 0.05 * w.second);
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
  // The first of the study's configurations at g = 0.9 where they differ at least two-fold.
  Config<double> p;
  Moments camera;
  for (const Config<double>& c : MakeConfigs(kDefaultSeed, 8, 0.9)) {
    p = c;
    camera = CameraStepMoments(p.query, p.xi_vrl);
    if (camera.RelativeVariance(0) > 2 * camera.RelativeVariance(1)) break;
  }
  REQUIRE(camera.RelativeVariance(0) > 2 * camera.RelativeVariance(1));
  Moments whole = WholeMoments(p.query);
  McMoments c_eq = CameraMc(p, 0, 200000, 1), w_eq = WholeMc(p.query, 0, 200000, 2);
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
    for (const Config<double>& p : MakeConfigs(kDefaultSeed, 4, g)) {
      Moments a = WholeMoments(p.query), b = WholeMoments(p.query, fine);
      Moments ca = CameraStepMoments(p.query, p.xi_vrl), cb = CameraStepMoments(p.query, p.xi_vrl, fine);
      REQUIRE(a.converged);
      REQUIRE(b.converged);
      for (int k = 0; k < kCameraSamplerCount; ++k) {
        INFO("g = " << g << ", " << Name(kSegmentSamplers[k]));
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
  // transmittance, so on average over these configurations (sigma_t from 0.05 to 5, where
  // transmittance is sometimes nearly flat) it must do better than equiangular sampling.
  double full = 0, equiangular = 0;
  for (const Config<double>& p : MakeConfigs(kDefaultSeed, 8, 0.0)) {
    Moments m = WholeMoments(p.query);
    for (int k = 1; k <= 3; ++k) CHECK(m.RelativeVariance(k) == Approx(m.RelativeVariance(0)).epsilon(1e-6));
    CHECK(Name(kSegmentSamplers[4]) == "full-product");
    full += m.RelativeVariance(4);
    equiangular += m.RelativeVariance(0);
  }
  INFO("mean relative variance: FullProduct " << full / 8 << ", equiangular " << equiangular / 8);
  CHECK(full < equiangular);
}
