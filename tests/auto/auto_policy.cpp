// Hypotheses:
// - the bound is an upper bound: for random queries (|g| up to 0.95, bounded segments up to
//   14 mean free paths, points near and far), the relative variance of equiangular sampling
//   computed by adaptive quadrature of the full target never exceeds
//   UniformVarianceBound(TargetRangeRatio) (up to the quadrature's tolerance);
// - auto keeps equiangular sampling (bit for bit) where the target is flat, and fits where
//   the bound exceeds the threshold.
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <catch2/catch.hpp>
#include <vrlis/vrlis.hpp>

#include <cmath>
#include <random>

namespace {

using Q = vrlis::SegmentQuery<double>;

double UniformRelativeVariance(const Q& q) {
  vrlis::AngleDomain<double> dom(q);
  vrlis::FullProductTarget<double> f(q, dom);
  const double w = dom.width();
  auto integrate = [&](auto g) {
    // Split at a grid so that narrow lobes are resolved.
    double sum = 0;
    const int pieces = 64;
    for (int i = 0; i < pieces; ++i)
      sum += boost::math::quadrature::gauss_kronrod<double, 31>::integrate(g, w * i / pieces, w * (i + 1) / pieces, 10, 1e-10);
    return sum;
  };
  double i1 = integrate([&](double x) { return f(x); }), i2 = integrate([&](double x) { return f(x) * f(x); });
  return w * i2 / (i1 * i1) - 1;
}

// Each factor of the target is sometimes the only one that varies (the other lobe flat or
// no extinction), so that a factor the bound left out would show as a violation.
Q RandomQuery(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  auto unit = [&] {
    double z = 2 * u(rng) - 1, phi = 2 * vrlis::kPi<double> * u(rng), s = std::sqrt(1 - z * z);
    return vrlis::Vec3<double>{s * std::cos(phi), s * std::sin(phi), z};
  };
  auto asymmetry = [&] { return u(rng) < 0.3 ? 0.0 : (2 * u(rng) - 1) * 0.95; };
  double sigma_t = u(rng) < 0.3 ? 0.0 : std::pow(10.0, -2 + 2 * u(rng));
  double length = std::pow(10.0, -1 + 2.5 * u(rng));
  if (sigma_t > 0) length = std::min(length, 14 / sigma_t);
  double h = std::pow(10.0, -2 + 2.5 * u(rng));
  vrlis::Vec3<double> dir = unit(), n = vrlis::Normalize(vrlis::Cross(dir, unit()));
  Q q = vrlis::MediumToMediumQuery<double>({0, 0, 0}, dir, 0, length, (length * (1.5 * u(rng) - 0.25)) * dir + h * n,
                                            unit(), asymmetry(), sigma_t);
  q.lobe.g = asymmetry();
  return q;
}

}  // namespace

TEST_CASE("the auto rule's bound is an upper bound of equiangular's relative variance") {
  std::mt19937_64 rng(12);
  int fitted = 0;
  for (int i = 0; i < 600; ++i) {
    Q q = RandomQuery(rng);
    vrlis::AngleDomain<double> dom(q);
    double bound = vrlis::UniformVarianceBound(vrlis::TargetRangeRatio(q, dom, vrlis::PhaseProduct<double>(q, dom)));
    double actual = UniformRelativeVariance(q);
    INFO("query " << i << ": g " << q.g << " point g " << q.lobe.g << " sigma_t " << q.sigma_t << " length " << q.tmax << " actual " << actual
                  << " bound " << bound);
    CHECK(actual <= bound * (1 + 1e-6) + 1e-9);
    fitted += vrlis::Auto<double>(q).distribution().fitted() ? 1 : 0;
  }
  // Both decisions occur on this distribution: the rule is not constant.
  CHECK(fitted > 60);
  CHECK(fitted < 540);
}

TEST_CASE("auto keeps equiangular sampling where the target is flat and fits where it is not") {
  Q flat = vrlis::MediumToMediumQuery<double>({0, 0, 0}, {0, 0, -1}, 0, 4, {0.5, 0, -2}, {1, 0, 0}, 0, 0);
  vrlis::Auto<double> a(flat);
  vrlis::Equiangular<double> e(flat);
  CHECK_FALSE(a.distribution().fitted());
  for (double u : {0.0, 0.1, 0.5, 0.93, 1.0}) {
    CHECK(a.sample(u) == e.sample(u));
    CHECK(a.pdf(e.sample(u)) == e.pdf(e.sample(u)));
  }
  Q mild = vrlis::MediumToMediumQuery<double>({0, 0, 0}, {0, 0, -1}, 0, 0.3, {2, 0, -0.1}, {1, 0, 0}, 0.2, 0.05);
  CHECK_FALSE(vrlis::Auto<double>(mild).distribution().fitted());
  Q peaked = vrlis::MediumToMediumQuery<double>({0, 0, 0}, {0, 0, -1}, 0, 4, {0.5, 0, -2}, {0, 0, -1}, 0.9, 0.3);
  CHECK(vrlis::Auto<double>(peaked).distribution().fitted());
  Q unbounded = vrlis::MediumToMediumQuery<double>({0, 0, 0}, {0, 0, -1}, 0, std::numeric_limits<double>::infinity(),
                                                   {0.5, 0, -2}, {1, 0, 0}, 0, 0.3);
  CHECK(vrlis::Auto<double>(unbounded).distribution().fitted());
}
