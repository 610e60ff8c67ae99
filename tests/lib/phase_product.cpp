// Hypothesis: PhaseProduct::evaluate, the vector loop every piecewise-linear fit (Novák,
// FullProduct) calls at its nodes, computes the same product as the pointwise operator()
// for each kind of point lobe (Henyey-Greenstein, clamped cosine, none), in float and
// double, to within rounding of the value and of the angle it is evaluated at. Without
// this, a wrong loop would go unnoticed: the samplers' own tests check a fit against its
// own density, whatever target it was fitted to. The fits' own call, evaluate<Accuracy::Fit>,
// within 1e-3 of the value and 1e-4 of the angle (core/lane_math.hpp's Accuracy; its sines
// to r^3 only would miss that by several times).
#include <catch2/catch.hpp>
#include <vrlis/vrlis.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <random>

namespace {

template <typename Real>
vrlis::Vec3<Real> RandomUnit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return vrlis::Normalize(vrlis::Vec3<Real>{Real(n(rng)), Real(n(rng)), Real(n(rng))});
}

vrlis::SegmentQuery<double> Widen(const vrlis::SegmentQuery<float>& q) {
  auto v = [](vrlis::Vec3<float> a) { return vrlis::Vec3<double>{a.x, a.y, a.z}; };
  return {v(q.origin), v(q.dir), q.tmin, q.tmax, q.g, v(q.point), {q.lobe.kind, v(q.lobe.axis), q.lobe.g}, q.sigma_t};
}
vrlis::SegmentQuery<double> Widen(const vrlis::SegmentQuery<double>& q) { return q; }

}  // namespace

TEMPLATE_TEST_CASE("PhaseProduct::evaluate equals the pointwise product at every node", "[lib]", float, double) {
  using Real = TestType;
  const double eps = std::numeric_limits<Real>::epsilon();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  const vrlis::LobeKind kinds[] = {vrlis::LobeKind::HenyeyGreenstein, vrlis::LobeKind::ClampedCosine,
                                   vrlis::LobeKind::None};
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    vrlis::SegmentQuery<Real> q;
    q.dir = RandomUnit<Real>(rng);
    q.tmin = Real(4 * unit(rng) - 2);
    q.tmax = i % 7 == 0 ? std::numeric_limits<Real>::infinity() : q.tmin + Real(0.01 + 10 * unit(rng));
    q.point = {Real(4 * unit(rng) - 2), Real(4 * unit(rng) - 2), Real(4 * unit(rng) - 2)};
    q.g = Real(1.8 * unit(rng) - 0.9);
    q.lobe = {kinds[i % 3], RandomUnit<Real>(rng), Real(1.8 * unit(rng) - 0.9)};
    const vrlis::AngleDomain<Real> dom(q);
    const vrlis::PhaseProduct<Real> target(q, dom);
    const vrlis::SegmentQuery<double> wide = Widen(q);
    const vrlis::AngleDomain<double> wide_dom(wide);
    const vrlis::PhaseProduct<double> reference(wide, wide_dom);  // for the slope only
    std::array<Real, 16> delta, out, fit;
    for (std::size_t j = 0; j < delta.size(); ++j) delta[j] = dom.width() * Real(j) / Real(delta.size() - 1);
    target.evaluate(delta, out);
    target.template evaluate<vrlis::Accuracy::Fit>(delta, fit);
    double largest = 0;
    for (Real d : delta) largest = std::max(largest, double(target(d)));
    for (std::size_t j = 0; j < delta.size(); ++j) {
      double p = target(delta[j]), step = 1e-6 * (1 + double(delta[j]));
      double slope = std::abs(reference(double(delta[j]) + step) - reference(double(delta[j]) - step)) / (2 * step);
      // Rounding of the value, and of the angle (an ulp of a few pi, in either evaluation).
      double tolerance = 64 * eps * (std::abs(p) + 1e-6 * largest) + slope * 16 * eps * (vrlis::kPi<double> + delta[j]);
      INFO("kind " << int(q.lobe.kind) << ", node " << j << ": evaluate " << out[j] << ", pointwise " << p);
      CHECK(std::abs(out[j] - p) <= tolerance);
      CHECK(std::abs(fit[j] - p) <= tolerance + 1e-3 * std::abs(p) + slope * 1e-4);
      ++checked;
    }
  }
  CHECK(checked == 3000 * 16);
}
