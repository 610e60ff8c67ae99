// With g = 0 (and a point lobe that is isotropic or absent) every sampler is
// equiangular sampling, to rounding.
#include <catch2/catch.hpp>

#include "checks.hpp"

using namespace vrlis::test;

namespace {

// Isotropic configurations: the random and hard ones at g = 0, minus the clamped-cosine
// lobes (a cosine lobe is anisotropic whatever g is).
std::vector<Config> IsotropicConfigs() {
  std::vector<Config> out;
  for (const Config& c : ConfigsFor(0.0))
    if (c.kind != vrlis::LobeKind::ClampedCosine) out.push_back(c);
  return out;
}

template <typename S, typename Real = typename S::Real>
void CheckCoincidesWithEquiangular(const Config& c, const std::vector<Real>& us) {
  const vrlis::SegmentQuery<Real> q = ToQuery<Real>(c);
  const vrlis::Equiangular<Real> e(q);
  const S s(q);
  const AngleMap m = MapFor(AsSeenBy<Real>(c));
  double worst_t = 0, worst_pdf = 0, worst_u = 0;
  for (Real u : us) {
    Real te = e.sample(u), ts = s.sample(u);
    // Compared as angles: both samplers draw an angle offset, which rounds relative to the
    // interval, and t_at amplifies that by dt/dtheta; the allowance is in the angle, plus
    // the rounding of t itself seen as an angle.
    double angle_gap = std::abs(m.theta(double(ts)) - m.theta(double(te)));
    double t_rounding = std::abs(double(te)) * m.h / (m.h * m.h + Square(double(te) - m.u0));
    worst_t = std::max(worst_t, angle_gap / (kPi + std::abs(m.theta_a) + t_rounding));
    worst_pdf = std::max(worst_pdf, std::abs(double(s.pdf(te)) / double(e.pdf(te)) - 1));
    worst_u = std::max(worst_u, std::abs(double(s.invert(te)) - double(e.invert(te))));
  }
  const std::string label = Label<S>();
  Summary::Get().Max(label, "g0_angle_difference_over_scale", worst_t, c.name);
  Summary::Get().Max(label, "g0_relative_pdf_difference", worst_pdf, c.name);
  Summary::Get().Max(label, "g0_invert_difference", worst_u, c.name);
  INFO(label << " vs Equiangular on " << c.name << ": t " << worst_t << " pdf " << worst_pdf << " invert " << worst_u);
  const double tol = 64 * double(std::numeric_limits<Real>::epsilon());
  CHECK(worst_t <= tol);
  CHECK(worst_pdf <= tol);
  CHECK(worst_u <= tol);
}

}  // namespace

TEMPLATE_TEST_CASE("g = 0: every camera sampler coincides with Equiangular", "[lib][g0]", float, double) {
  using Real = TestType;
  Summary::Get().SetFile(std::string("g0-") + RealName<Real>());
  std::vector<Real> us = UniformNumbers<Real>(2024, 2000);
  for (int i = 0; i <= 64; ++i) us.push_back(Real(i) / 64);
  // sigma_t = 0: FullProduct's target (and auto's bound) is the phase product, constant here.
  for (const Config& c : IsotropicConfigs())
    ForEachSegmentSampler<Real>([&](auto tag) { CheckCoincidesWithEquiangular<typename decltype(tag)::type>(c, us); });
}
