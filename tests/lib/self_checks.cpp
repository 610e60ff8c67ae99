// The tests' own machinery, checked: the quadrature against closed forms (on the peaked
// integrands the battery meets), and the chi-square test's power to reject a wrong pdf or
// a wrong sampler. A test suite that cannot fail tests nothing.
#include <catch2/catch.hpp>

#include "checks.hpp"

using namespace vrlis::test;

TEST_CASE("quadrature reproduces closed forms on peaked integrands", "[lib][self]") {
  // The inverse square over a segment, in the angle map: (theta_b - theta_a) / h.
  for (double h : {1e-3, 0.05, 2.0}) {
    Config c;
    c.origin = {0, 0, 0};
    c.dir = {1, 0, 0};
    c.tmin = -0.3;
    c.tmax = 7;
    c.point = {0.4, h, 0};
    AngleMap m = MapFor(c);
    auto inv_sq = [&](double th) {
      double t = m.t(th);
      return m.dt_dtheta(th) / (Square(t - 0.4) + h * h);
    };
    double q = Sum(CellIntegrals(inv_sq, RefinedGrid(m.theta_a, m.theta_b, {0.0})));
    double exact = (std::atan((7 - 0.4) / h) - std::atan((-0.3 - 0.4) / h)) / h;
    CHECK(std::abs(q / exact - 1) < 1e-12);
  }
  // A Cauchy spike of width 1e-6 rad, as fitted for g = 0.99, inside an interval.
  for (double gamma : {1e-6, 1e-4}) {
    double mu = 0.3, a = -1, b = 1.2;
    auto cauchy = [&](double x) { return gamma / (kPi * (Square(x - mu) + gamma * gamma)); };
    double q = Sum(CellIntegrals(cauchy, RefinedGrid(a, b, {mu})));
    double exact = (std::atan((b - mu) / gamma) - std::atan((a - mu) / gamma)) / kPi;
    CHECK(std::abs(q / exact - 1) < 1e-11);
  }
  // The reference Henyey-Greenstein integrates to one over the sphere, peaks included.
  for (double g : {-0.99, -0.5, 0.0, 0.9, 0.99}) {
    auto hg = [&](double cos) {
      V3 a{0, 0, 1}, b{std::sqrt(std::max(0.0, 1 - cos * cos)), 0, cos};
      return 2 * kPi * HgBetween(g, a, b);
    };
    double q = Sum(CellIntegrals(hg, RefinedGrid(-1, 1, {})));
    CHECK(std::abs(q - 1) < 1e-10);
  }
}

TEST_CASE("the chi-square test rejects a perturbed pdf and a perturbed sampler", "[lib][self]") {
  const Config c = HardConfigs(0.9)[0];  // peak inside
  const vrlis::CauchySum<double> s(ToQuery<double>(c));
  const AngleMap m = MapFor(c);
  const std::vector<double> features = FeatureAngles(c, m);
  auto pdf_theta = [&](double th) { return s.pdf(m.t(th)) * m.dt_dtheta(th); };
  auto t_of_theta = [&](double th) { return m.t(th); };
  const std::vector<double> u = UniformNumbers<double>(77, kSamples);
  std::vector<double> theta, theta_warped;
  for (double x : u) {
    theta.push_back(m.theta(s.sample(x)));
    theta_warped.push_back(m.theta(s.sample(x + 0.2 * x * (1 - x))));  // u distorted by up to 5%
  }
  ChiSquare right = BinnedChiSquare<double>(pdf_theta, t_of_theta, m.theta_a, m.theta_b, features, theta);
  INFO("correct: chi-square " << right.statistic << " dof " << right.dof << " p " << right.p_value);
  CHECK(right.Passes());
  // The density with a 20% ripple (a 5% tilt is below what 20000 samples can see at this
  // significance: its noncentrality is only about 4).
  auto tilted = [&](double th) {
    return pdf_theta(th) * (1 + 0.2 * std::sin(6 * kPi * (th - m.theta_a) / (m.theta_b - m.theta_a)));
  };
  ChiSquare wrong_pdf = BinnedChiSquare<double>(tilted, t_of_theta, m.theta_a, m.theta_b, features, theta);
  INFO("tilted pdf: chi-square " << wrong_pdf.statistic << " dof " << wrong_pdf.dof << " p " << wrong_pdf.p_value);
  CHECK_FALSE(wrong_pdf.Passes());
  ChiSquare wrong_sampler = BinnedChiSquare<double>(pdf_theta, t_of_theta, m.theta_a, m.theta_b, features, theta_warped);
  INFO("warped sampler: chi-square " << wrong_sampler.statistic << " dof " << wrong_sampler.dof << " p "
                                     << wrong_sampler.p_value);
  CHECK_FALSE(wrong_sampler.Passes());
  Summary::Get().SetFile("self");
  Summary::Get().Count("all", "chi_square_tests", 3);
}
