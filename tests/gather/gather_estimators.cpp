// Hypothesis, for every gather estimator and configuration: the mean of the weights f / pdf
// equals the integral of f (computed by adaptive Gauss-Kronrod quadrature). Each mean is
// compared by its z-score against the two-sided normal critical value at 1 % overall,
// Bonferroni-corrected over every comparison in this file; each case also checks that the
// same samples reject an integral 10 % off (the test can fail). An RGB medium sampled through
// its grey query: each channel's GatherSample::weight_for against that channel's integral.
// Samples: kSamples divided by VRLIS_TEST_DIVISOR (divisor.hpp); the 10 % controls' smallest
// z, 15 at the full count, stays clear of the critical value 4 down to a divisor of 8.
#include <boost/math/distributions/normal.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <catch2/catch.hpp>
#include <vrlis/core/running_moments.hpp>
#include <vrlis/vrlis.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "divisor.hpp"

namespace {

using vrlis::Vec3;
constexpr double kInf = std::numeric_limits<double>::infinity();
// medium, surface, point light x float, double; an RGB medium's channels (3 cases x 2 samplers x 3)
constexpr int kComparisons = 3 * 10 * 2 + 3 * 5 * 2 + 3 * 5 * 2 + 3 * 2 * 3;
const int kSamples = int(vrlis::test::Divided(200000));

double Critical() {
  return boost::math::quantile(boost::math::normal(), 1 - 0.01 / (2 * kComparisons));
}

template <typename F>
double Integrate(F f, double a, double b) {
  return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, a, b, 12, 1e-9);
}

// Mean and standard error of n estimates drawn by estimate(u1, u2).
template <typename Real, typename Estimate>
std::pair<double, double> MeanAndError(Estimate estimate, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0, 1);
  vrlis::RunningMoments weights;
  for (int i = 0; i < n; ++i) {
    const Real u1 = Real(uniform(rng)), u2 = Real(uniform(rng));  // named: argument order is unspecified
    double w = estimate(u1, u2);
    REQUIRE(std::isfinite(w));
    weights.add(w);
  }
  return {weights.mean(), weights.standard_error()};
}

void CheckUnbiased(const std::string& what, std::pair<double, double> estimate, double integral) {
  auto [mean, error] = estimate;
  double z = (mean - integral) / error, z_control = (mean - 1.1 * integral) / error;
  std::printf("[gather] %-60s mean %.6g quadrature %.6g z %+.2f (10%% control z %+.1f)\n", what.c_str(), mean,
              integral, z, z_control);
  INFO(what << ": mean " << mean << " +- " << error << ", quadrature " << integral);
  CHECK(std::abs(z) < Critical());
  CHECK(std::abs(z_control) > Critical());
}

template <typename Real>
vrlis::RaySegment<Real> Camera(double tmax) {
  return {{0, 0, 0}, {0, 0, -1}, Real(0.5), Real(tmax)};
}
template <typename Real>
vrlis::VrlSegment<Real> Vrl(Vec3<double> o, Vec3<double> d, double length) {
  Vec3<double> n = vrlis::Normalize(d);
  return {{Real(o.x), Real(o.y), Real(o.z)}, {Real(n.x), Real(n.y), Real(n.z)}, Real(length)};
}

// Three configurations: a short bounded segment and an oblique VRL in a dense forward
// medium, a long one with a nearly parallel VRL in a backward medium, an unbounded one.
template <typename Real>
vrlis::MediumGatherQuery<Real> MediumCase(int k) {
  switch (k) {
    case 0: return {Camera<Real>(4), Vrl<Real>({0.6, -0.4, -1}, {1, 1, -0.5}, 3),
        vrlis::Medium<Real>::FromScatteringExtinction(Real(0.7), Real(0.6), Real(1))};
    case 1: return {Camera<Real>(12), Vrl<Real>({0.3, 0.2, -2}, {0.1, 0, -1}, 8),
        vrlis::Medium<Real>::FromScatteringExtinction(Real(-0.6), Real(0.2), Real(0.35))};
  }
  return {Camera<Real>(std::numeric_limits<Real>::infinity()), Vrl<Real>({-1, 0.5, -3}, {0, 1, 0.3}, 5),
          vrlis::Medium<Real>::FromScatteringExtinction(Real(0.5), Real(0.5), Real(0.8))};
}

template <typename Real>
double MediumIntegral(const vrlis::MediumGatherQuery<Real>& qr) {
  vrlis::MediumGatherQuery<double> q{{vrlis::Vec3<double>{qr.camera.origin.x, qr.camera.origin.y, qr.camera.origin.z},
                                      {qr.camera.dir.x, qr.camera.dir.y, qr.camera.dir.z}, qr.camera.tmin,
                                      std::isfinite(qr.camera.tmax) ? double(qr.camera.tmax) : kInf},
                                     {{qr.vrl.origin.x, qr.vrl.origin.y, qr.vrl.origin.z},
                                      {qr.vrl.dir.x, qr.vrl.dir.y, qr.vrl.dir.z}, qr.vrl.length},
                                     vrlis::Medium<double>::FromScatteringExtinction(qr.medium.g, qr.medium.sigma_s,
                                                                                     qr.medium.sigma_t)};
  return Integrate([&](double v) {
    return Integrate([&](double t) { return vrlis::MediumGatherIntegrand(q, t, v); }, q.camera.tmin, q.camera.tmax);
  }, 0.0, q.vrl.length);
}

template <typename Real>
void MediumGatherIsUnbiased(const char* type) {
  for (int k = 0; k < 3; ++k) {
    vrlis::MediumGatherQuery<Real> q = MediumCase<Real>(k);
    double integral = MediumIntegral(q);
    for (vrlis::VrlChoice one : vrlis::kVrlSamplers)
      for (vrlis::SegmentChoice two : vrlis::kSegmentSamplers) {
        vrlis::GatherSamplers m{two, one};
        auto estimate = MeanAndError<Real>(
            [&](Real u1, Real u2) { return double(vrlis::SampleMediumGather(m, q, u1, u2).weight); }, kSamples, 7 + k);
        CheckUnbiased(std::string(type) + " medium case " + std::to_string(k) + " " + vrlis::Name(m), estimate, integral);
      }
  }
}

// An RGB medium sampled through its grey query medium: each channel's weight_for, averaged,
// is that channel's integral (the query's g, the channel's coefficients). Two samplers: one
// whose sampling ignores sigma_t, one (FullProduct) whose sampling follows the grey sigma_t.
template <typename Real>
void MediumChannelsAreUnbiased() {
  const double extinction[3] = {0.6, 1, 1.7}, albedo[3] = {0.9, 0.5, 0.2};
  for (int k = 0; k < 3; ++k) {
    const vrlis::MediumGatherQuery<Real> q = MediumCase<Real>(k);
    vrlis::Medium<Real> channel[3];
    double integral[3];
    for (int c = 0; c < 3; ++c) {
      const Real sigma_t = Real(q.medium.sigma_t * extinction[c]);
      channel[c] = vrlis::Medium<Real>::FromScatteringExtinction(q.medium.g, Real(albedo[c]) * sigma_t, sigma_t);
      integral[c] = MediumIntegral(vrlis::MediumGatherQuery<Real>{q.camera, q.vrl, channel[c]});
    }
    for (const char* name : {"novak", "full-product+marginal"}) {
      const vrlis::GatherSamplers m = *vrlis::ParseGatherSamplers(name);
      std::mt19937_64 rng(37 + k);
      std::uniform_real_distribution<double> uniform(0, 1);
      vrlis::RunningMoments weights[3];
      for (int i = 0; i < kSamples; ++i) {
        const Real u1 = Real(uniform(rng)), u2 = Real(uniform(rng));
        const vrlis::GatherSample<Real> s = vrlis::SampleMediumGather(m, q, u1, u2);
        for (int c = 0; c < 3; ++c) weights[c].add(double(s.weight_for(channel[c])));
      }
      for (int c = 0; c < 3; ++c)
        CheckUnbiased("RGB medium case " + std::to_string(k) + " channel " + std::to_string(c) + " " + name,
                      {weights[c].mean(), weights[c].standard_error()}, integral[c]);
    }
  }
}

template <typename Real>
vrlis::SurfaceGatherQuery<Real> SurfaceCase(int k) {
  Vec3<Real> p{0, -1, -2}, n{0, 1, 0};
  switch (k) {
    case 0: return {p, n, Vrl<Real>({-1, 0.5, -2.5}, {1, 0.2, 0}, 3),
        vrlis::Medium<Real>::FromScatteringExtinction(Real(0.8), Real(0.5), Real(0.7))};
    case 1: return {p, n, Vrl<Real>({0.5, 3, -2}, {0, -1, 0.1}, 4.5),
        vrlis::Medium<Real>::FromScatteringExtinction(Real(-0.5), Real(0.3), Real(0.4))};
  }
  return {p, n, Vrl<Real>({-3, -0.5, -2}, {1, 0, 0}, 6),
      vrlis::Medium<Real>::FromScatteringExtinction(Real(0.3), Real(0.9), Real(1.2))};
}

template <typename Real>
void SurfaceGatherIsUnbiased(const char* type) {
  for (int k = 0; k < 3; ++k) {
    vrlis::SurfaceGatherQuery<Real> q = SurfaceCase<Real>(k);
    double integral = Integrate([&](double v) { return double(vrlis::SurfaceGatherIntegrand(q, Real(v))); }, 0.0,
                                q.vrl.length);
    for (vrlis::SegmentChoice m : vrlis::kSegmentSamplers) {
      auto estimate = MeanAndError<Real>(
          [&](Real u, Real) { return double(vrlis::SampleSurfaceGather(m, q, u).weight); }, kSamples, 17 + k);
      CheckUnbiased(std::string(type) + " surface case " + std::to_string(k) + " " + std::string(vrlis::Name(m)),
                    estimate, integral);
    }
  }
}

template <typename Real>
void PointLightGatherIsUnbiased(const char* type) {
  const Vec3<Real> lights[3] = {{Real(0.5), 0, -2}, {0, Real(0.05), -6}, {2, 1, Real(0.5)}};
  const double tmax[3] = {4, 10, kInf};
  for (int k = 0; k < 3; ++k) {
    vrlis::PointLightGatherQuery<Real> q{Camera<Real>(tmax[k]), lights[k],
        vrlis::Medium<Real>::FromScatteringExtinction(Real(k == 1 ? -0.8 : 0.6), Real(0.4), Real(0.6))};
    double integral = Integrate([&](double t) { return double(vrlis::PointLightGatherIntegrand(q, Real(t))); },
                                double(q.camera.tmin), tmax[k]);
    for (vrlis::SegmentChoice m : vrlis::kSegmentSamplers) {
      auto estimate = MeanAndError<Real>(
          [&](Real u, Real) { return double(vrlis::SamplePointLightGather(m, q, u).weight); }, kSamples, 27 + k);
      CheckUnbiased(std::string(type) + " point light case " + std::to_string(k) + " " + std::string(vrlis::Name(m)),
                    estimate, integral);
    }
  }
}

}  // namespace

TEST_CASE("medium-to-medium gather: every step one x step two is unbiased (double)") { MediumGatherIsUnbiased<double>("double"); }
TEST_CASE("medium-to-medium gather: every step one x step two is unbiased (float)") { MediumGatherIsUnbiased<float>("float"); }
TEST_CASE("medium-to-surface gather: every sampler is unbiased (double)") { SurfaceGatherIsUnbiased<double>("double"); }
TEST_CASE("medium-to-surface gather: every sampler is unbiased (float)") { SurfaceGatherIsUnbiased<float>("float"); }
TEST_CASE("point-light gather: every sampler is unbiased (double)") { PointLightGatherIsUnbiased<double>("double"); }
TEST_CASE("point-light gather: every sampler is unbiased (float)") { PointLightGatherIsUnbiased<float>("float"); }
TEST_CASE("medium-to-medium gather: an RGB medium's channel weights are unbiased (float)") {
  MediumChannelsAreUnbiased<float>();
}
