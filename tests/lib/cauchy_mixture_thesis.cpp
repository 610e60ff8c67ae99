// CauchyMixture is the thesis's mixture (docs/maths.md#cauchy-mixture): its density equals,
// to rounding, 1/2 C_1 / N_1 + 1/2 C_2 / N_2, each Cauchy of the thesis's fit truncated to
// the angle interval on its own. The reference is rebuilt here from the query's geometry in
// double, without the library's angle domain, phase product or fit.
#include <catch2/catch.hpp>

#include "checks.hpp"

using namespace vrlis::test;

namespace {

double HgPeak(double g, double cos) { return (1 - g * g) / (4 * kPi * std::pow(1 + g * g - 2 * std::abs(g) * cos, 1.5)); }

// atan((b - mu) / gamma) - atan((a - mu) / gamma) for a < b, without the cancellation of
// two nearly equal arctangents next to a narrow peak.
double CauchyMass(double a, double b, double mu, double gamma) {
  double xa = (a - mu) / gamma, xb = (b - mu) / gamma, den = 1 + xa * xb;
  double d = std::atan((xb - xa) / std::abs(den));
  return den > 0 ? d : kPi - d;
}

struct ThesisCauchy {
  double mu, gamma, mass;
  double density(double theta) const { return gamma / (Square(theta - mu) + Square(gamma)) / mass; }
};

// The thesis's mixture for a medium-to-medium query, as a density in t.
struct ThesisMixture {
  AngleMap m;
  ThesisCauchy lobe[2];

  explicit ThesisMixture(const Config& c) : m(MapFor(c)) {
    V3 foot = c.origin + m.u0 * c.dir, n = Unit(c.point - foot);
    double a = -Dot(c.axis, n), b = Dot(c.axis, c.dir), r = std::sqrt(a * a + b * b);
    // Along the segment the cosine is -sin(theta); at the point, r cos(theta - theta_e).
    double segment_peak = c.g > 0 ? -kPi / 2 : kPi / 2;
    double point_peak = std::atan2(b, a) + (c.lobe_g < 0 ? kPi : 0), middle = (m.theta_a + m.theta_b) / 2;
    point_peak -= 2 * kPi * std::round((point_peak - middle) / (2 * kPi));  // the image nearest the interval
    Set(0, segment_peak, HgPeak(c.g, 1));
    Set(1, point_peak, HgPeak(c.lobe_g, r));
  }
  void Set(int k, double mu, double peak_value) {
    double gamma = 1 / (kPi * peak_value);  // the Cauchy's peak 1 / (pi gamma) is the lobe's
    lobe[k] = {mu, gamma, CauchyMass(m.theta_a, m.theta_b, mu, gamma)};
  }
  double pdf(double t) const {
    double theta = m.theta(t);
    return (lobe[0].density(theta) + lobe[1].density(theta)) / 2 * m.h / (Square(m.h) + Square(t - m.u0));
  }
};

template <typename S>
double WorstRelativeGap(const Config& c) {
  const vrlis::SegmentQuery<double> q = ToQuery<double>(c);
  const S s(q);
  const ThesisMixture reference(c);
  double worst = 0;
  for (double u : UniformNumbers<double>(77, 200)) {
    double t = c.tmin + u * (c.tmax - c.tmin);
    worst = std::max(worst, std::abs(double(s.pdf(t)) / reference.pdf(t) - 1));
  }
  return worst;
}

}  // namespace

TEST_CASE("CauchyMixture's density is the thesis's equal-weight mixture", "[lib][cauchy-mixture]") {
  int checked = 0;
  double worst_other = 0;
  for (double g : {-0.99, -0.9, -0.5, -0.3, 0.3, 0.5, 0.9, 0.99}) {
    for (int i = 0; i < kRandomConfigsPerG; ++i) {
      Config c = RandomConfig(g, i);
      if (c.kind != vrlis::LobeKind::HenyeyGreenstein) continue;  // the thesis's mixture has two HG lobes
      double gap = WorstRelativeGap<vrlis::CauchyMixture<double>>(c);
      INFO("g " << g << ", " << c.name);
      CHECK(gap <= 1e-9);
      // The test tells densities apart: the Cauchy sum (weights proportional to the masses)
      // fails it.
      worst_other = std::max(worst_other, WorstRelativeGap<vrlis::CauchySum<double>>(c));
      ++checked;
    }
  }
  CHECK(checked >= 100);
  CHECK(worst_other > 0.1);
}
