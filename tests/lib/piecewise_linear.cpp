// PiecewiseLinear (core/piecewise_linear.hpp) on its own, in float and double: it
// integrates to one, its samples follow its pdf (chi-square), its cdf undoes sample, and
// sample_pdf agrees with pdf(sample); including a node of value zero and equal nodes (a
// jump), which the fits produce.
#include <catch2/catch.hpp>

#include <vrlis/core/piecewise_linear.hpp>

#include "checks.hpp"

using namespace vrlis::test;

namespace {

struct Shape {
  const char* name;
  std::vector<double> nodes, values;
};

const Shape kShapes[] = {
    {"two nodes, rising", {0, 1}, {0.2, 3}},
    {"ten uneven nodes", {-1, -0.9, -0.5, 0, 0.1, 0.15, 0.7, 1.5, 2, 4}, {1, 3, 0.5, 8, 2, 2, 0.01, 4, 1, 0.3}},
    {"a node of value zero", {0, 0.3, 0.5, 1}, {1, 2, 0, 1.5}},
    {"zero at both ends", {2, 2.5, 3}, {0, 1, 0}},
    {"equal nodes: a jump", {0, 0.3, 0.3, 0.6, 1}, {1, 2, 6, 4, 1}},
    {"equal nodes at the end", {0, 0.5, 1, 1}, {1, 2, 3, 9}},
};

template <typename Real, int N>
vrlis::PiecewiseLinear<Real, N> Make(const Shape& s) {
  std::array<Real, N> x{}, f{};
  for (std::size_t j = 0; j < s.nodes.size(); ++j) {
    x[j] = Real(s.nodes[j]);
    f[j] = Real(s.values[j]);
  }
  return vrlis::PiecewiseLinear<Real, N>(x, f, int(s.nodes.size()));
}

}  // namespace

TEMPLATE_TEST_CASE("PiecewiseLinear: normalisation, chi-square, cdf round trip, sample_pdf", "[lib][piecewise]", float,
                   double) {
  using Real = TestType;
  Summary::Get().SetFile(std::string("piecewise-") + RealName<Real>());
  const double eps = std::numeric_limits<Real>::epsilon();
  std::uint64_t seed = 3;
  for (const Shape& shape : kShapes) {
    INFO(shape.name << " / " << RealName<Real>());
    const auto d = Make<Real, 10>(shape);
    const double a = shape.nodes.front(), b = shape.nodes.back();
    auto pdf = [&](double x) { return double(d.pdf(Real(x))); };

    // Normalisation: the pdf is linear between nodes, so Gauss-Kronrod per interval is exact.
    double mass = 0;
    for (std::size_t j = 0; j + 1 < shape.nodes.size(); ++j) mass += Integrate(pdf, shape.nodes[j], shape.nodes[j + 1], 1e-12, 0);
    CHECK(std::abs(mass - 1) <= 64 * eps);
    CHECK(d.pdf(Real(a) - 1) == 0);
    CHECK(d.pdf(Real(b) + 1) == 0);
    CHECK(d.cdf(Real(a)) == 0);
    CHECK(d.cdf(Real(b)) == 1);

    double largest = 0;
    for (double node : shape.nodes) largest = std::max(largest, double(d.pdf(Real(node))));
    const std::vector<Real> u = UniformNumbers<Real>(0x9e3779b97f4a7c15ull * seed++, kSamples);
    std::vector<double> x(u.size());
    long outside = 0, round_trip_failures = 0, fused_failures = 0, zero_density = 0;
    double worst_round_trip = 0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      vrlis::SegmentSample<Real> s = d.sample_pdf(u[i]);
      x[i] = double(s.t);
      if (!(x[i] >= a && x[i] <= b) || s.t != d.sample(u[i])) ++outside;
      if (!(s.pdf > 0)) ++zero_density;
      // The pdf is continuous except at equal nodes, where either side is a valid value.
      Real p = d.pdf(s.t);
      bool at_jump = false;
      for (std::size_t j = 0; j + 1 < shape.nodes.size(); ++j)
        at_jump = at_jump || (shape.nodes[j] == shape.nodes[j + 1] && x[i] == double(Real(shape.nodes[j])));
      // Both round x, which moves a sloped pdf by up to an ulp of the node span times the slope.
      if (!(std::abs(double(s.pdf) - double(p)) <= 64 * eps * largest) && !at_jump) ++fused_failures;
      // cdf(sample(u)) = u up to the rounding of x (moving the cdf by pdf dx) and of u.
      double err = std::abs(double(d.cdf(s.t)) - double(u[i]));
      worst_round_trip = std::max(worst_round_trip, err);
      if (!(err <= 16 * eps * (1 + double(p) * (std::abs(x[i]) + std::abs(a) + std::abs(b))))) ++round_trip_failures;
    }
    CHECK(outside == 0);
    CHECK(zero_density == 0);
    CHECK(fused_failures == 0);
    INFO("worst |cdf(sample(u)) - u| " << worst_round_trip);
    CHECK(round_trip_failures == 0);

    ChiSquare chi = BinnedChiSquare<Real>(pdf, [](double t) { return t; }, a, b, shape.nodes, x);
    Summary::Get().Count("all", "chi_square_tests");
    INFO("chi-square " << chi.statistic << " dof " << chi.dof << " p " << chi.p_value);
    CHECK(chi.Passes());
  }
}

TEST_CASE("PiecewiseLinear: the chi-square test sees a wrong value", "[lib][piecewise]") {
  // Samples of one shape against the pdf of the same shape with one value 20% off.
  const Shape right = kShapes[1];
  Shape wrong = right;
  wrong.values[3] *= 1.2;
  const auto d = Make<double, 10>(right), w = Make<double, 10>(wrong);
  std::vector<double> x;
  for (double u : UniformNumbers<double>(11, kSamples)) x.push_back(d.sample(u));
  auto identity = [](double t) { return t; };
  ChiSquare chi = BinnedChiSquare<double>([&](double t) { return w.pdf(t); }, identity, -1, 4, right.nodes, x);
  Summary::Get().SetFile("piecewise-self");
  Summary::Get().Count("all", "chi_square_tests");
  INFO("chi-square " << chi.statistic << " dof " << chi.dof << " p " << chi.p_value);
  CHECK_FALSE(chi.Passes());
}
