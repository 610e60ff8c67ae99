// The two-point direction density (vrlis/core/two_point_direction.hpp): it integrates to one
// over the sphere, its samples follow it, its inverse round-trips, and the property it exists
// for: a ray's integral of 1 / |x - b|^2, divided by the density, is pi^3 / |b - a| for every
// direction, so the estimate it feeds is bounded.
#include <catch2/catch.hpp>

#include <random>

#include <vrlis/core/two_point_direction.hpp>

#include "../support/checks.hpp"
#include "../support/stats.hpp"

namespace {

using namespace vrlis::test;
using V = vrlis::Vec3<double>;

V RandomDirection(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return vrlis::Normalize(V{n(rng), n(rng), n(rng)});
}

// The angle of w about the axis from a perpendicular of our own (not the header's frame).
double Azimuth(V axis, V w) {
  V x = vrlis::Normalize(vrlis::Cross(axis, std::abs(axis.x) < 0.9 ? V{1, 0, 0} : V{0, 1, 0}));
  V y = vrlis::Cross(axis, x);
  double phi = std::atan2(vrlis::Dot(w, y), vrlis::Dot(w, x));
  return phi < 0 ? phi + 2 * M_PI : phi;
}

// Int_0^inf dt / |a + t w - b|^2 by quadrature, split at the point closest to b; the tail past
// t1 is 1 / (t1 - t0) to first order.
double InverseSquareAlongRay(V a, V w, V b) {
  V d = b - a;
  double t0 = vrlis::Dot(d, w), h2 = vrlis::Dot(d, d) - t0 * t0;
  auto f = [&](double t) { return 1 / (h2 + (t - t0) * (t - t0)); };
  double h = std::sqrt(std::max(h2, 0.0)), t1 = std::max(t0, 0.0) + 1e6 * (h + vrlis::Length(d));
  double sum = 0, lo = 0;
  for (double k : {-64.0, -8.0, -1.0, 0.0, 1.0, 8.0, 64.0, 4096.0}) {
    double hi = t0 + k * h;
    if (hi <= lo) continue;
    sum += Integrate(f, lo, hi, 1e-12);
    lo = hi;
  }
  return sum + Integrate(f, lo, t1, 1e-12) + 1 / (t1 - t0);
}

}  // namespace

TEST_CASE("TwoPointDirection: the density integrates to one over the sphere", "[lib][two-point]") {
  const V axis = vrlis::Normalize(V{0.3, -0.5, 0.8});
  const V x = vrlis::Normalize(vrlis::Cross(axis, V{1, 0, 0})), y = vrlis::Cross(axis, x);
  // Over alpha and phi with the solid angle's sin alpha: the density's 1 / sin alpha cancels.
  auto over_phi = [&](double alpha) {
    auto f = [&](double phi) {
      V w = (std::sin(alpha) * std::cos(phi)) * x + (std::sin(alpha) * std::sin(phi)) * y + std::cos(alpha) * axis;
      return vrlis::TwoPointDirectionPdf(axis, w) * std::sin(alpha);
    };
    return Integrate(f, 0, 2 * M_PI, 1e-10);
  };
  CHECK(Integrate(over_phi, 1e-9, M_PI, 1e-9) == Approx(1).epsilon(1e-6));
  CHECK(Integrate([](double a) { return vrlis::TwoPointAnglePdf(a); }, 0, M_PI, 1e-12) == Approx(1).epsilon(1e-9));
}

TEST_CASE("TwoPointDirection: a ray's inverse squared distance over the density is pi^3 / D", "[lib][two-point]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  double worst = 0;
  for (int i = 0; i < 200; ++i) {
    V a = 3.0 * RandomDirection(rng), b = (0.1 + 4 * u(rng)) * RandomDirection(rng);
    V axis = vrlis::Normalize(b - a);
    const double u1 = u(rng), u2 = u(rng);
    V w = vrlis::SampleTwoPointDirection(axis, u1, u2);
    double ratio = InverseSquareAlongRay(a, w, b) / vrlis::TwoPointDirectionPdf(axis, w);
    worst = std::max(worst, std::abs(ratio * vrlis::Length(b - a) / (M_PI * M_PI * M_PI) - 1));
  }
  INFO("worst relative deviation from pi^3 / D: " << worst);
  CHECK(worst < 1e-5);
}

TEMPLATE_TEST_CASE("TwoPointDirection: samples follow the density and invert", "[lib][two-point]", float, double) {
  using Real = TestType;
  using R3 = vrlis::Vec3<Real>;
  Summary::Get().SetFile(std::string("two-point-") + RealName<Real>());
  std::mt19937_64 rng(11);
  const V axis = RandomDirection(rng);
  const R3 axis_r{Real(axis.x), Real(axis.y), Real(axis.z)};
  const long n = 200000;
  std::vector<Real> u1 = UniformNumbers<Real>(3, n), u2 = UniformNumbers<Real>(4, n);
  std::vector<double> alpha(static_cast<std::size_t>(n)), phi(static_cast<std::size_t>(n));
  double worst_round_trip = 0;
  for (std::size_t i = 0; i < alpha.size(); ++i) {
    R3 w = vrlis::SampleTwoPointDirection(axis_r, u1[i], u2[i]);
    V wd{double(w.x), double(w.y), double(w.z)};
    alpha[i] = vrlis::AngleBetween(axis, wd);
    phi[i] = Azimuth(axis, wd) / (2 * M_PI);
    auto [v1, v2] = vrlis::InvertTwoPointDirection(axis_r, w);
    // The azimuth is undefined along the axis, and wraps at u2 = 0 = 1.
    double e2 = std::abs(double(v2) - double(u2[i]));
    if (alpha[i] > 1e-2) worst_round_trip = std::max(worst_round_trip, std::min(e2, 1 - e2));
    worst_round_trip = std::max(worst_round_trip, std::abs(double(v1) - double(u1[i])));
  }
  const double eps = double(std::numeric_limits<Real>::epsilon());
  INFO("worst |invert(sample(u)) - u| " << worst_round_trip);
  CHECK(worst_round_trip < 256 * eps);

  ChiSquare chi = BinnedChiSquare<Real>([](double a) { return vrlis::TwoPointAnglePdf(a); },
                                        [](double a) { return a; }, 0, M_PI, {}, alpha);
  Summary::Get().Count("all", "chi_square_tests");
  INFO("alpha: chi-square " << chi.statistic << " dof " << chi.dof << " p " << chi.p_value);
  CHECK(chi.Passes());
  ChiSquare chi_phi = UniformityChiSquare(phi);
  Summary::Get().Count("all", "chi_square_tests");
  INFO("phi: chi-square " << chi_phi.statistic << " dof " << chi_phi.dof << " p " << chi_phi.p_value);
  CHECK(chi_phi.Passes());
}

TEST_CASE("TwoPointDirection: the chi-square test sees a wrong density", "[lib][two-point]") {
  Summary::Get().SetFile("two-point-self");
  // Samples of the density against (pi - alpha)^2, the shape a squared sabotage would give.
  std::vector<double> alpha;
  for (double u : UniformNumbers<double>(5, 200000)) alpha.push_back(vrlis::SampleTwoPointAngle(u));
  auto wrong = [](double a) { return 3 * (M_PI - a) * (M_PI - a) / (M_PI * M_PI * M_PI); };
  ChiSquare chi = BinnedChiSquare<double>(wrong, [](double a) { return a; }, 0, M_PI, {}, alpha);
  Summary::Get().Count("all", "chi_square_tests");
  INFO("chi-square " << chi.statistic << " dof " << chi.dof << " p " << chi.p_value);
  CHECK_FALSE(chi.Passes());
}
