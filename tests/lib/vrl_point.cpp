// VrlPoint: the density 1 / distance(y(v), camera line) on the VRL, random and
// hard configurations (parallel, near-parallel, intersecting lines, tiny h, long VRLs), in
// float and double; and the two-step estimator of the medium-to-medium double integral.
#include <catch2/catch.hpp>

#include "checks.hpp"

using namespace vrlis::test;

namespace {

struct LineConfig {
  std::string name;
  V3 origin, dir;  // the VRL y(v) = origin + v dir
  double tmin = 0, tmax = 1;
  V3 line_origin, line_dir;  // the camera line
};

template <typename Real>
vrlis::VrlPointQuery<Real> ToPointQuery(const LineConfig& c) {
  return {ToVec<Real>(c.origin), ToVec<Real>(c.dir), Real(c.tmin), Real(c.tmax), ToVec<Real>(c.line_origin),
          ToVec<Real>(c.line_dir)};
}

template <typename Real>
LineConfig LineAsSeenBy(const LineConfig& c) {
  auto q = ToPointQuery<Real>(c);
  LineConfig r = c;
  r.origin = FromVec(q.origin);
  r.dir = FromVec(q.dir);
  r.tmin = double(q.tmin);
  r.tmax = double(q.tmax);
  r.line_origin = FromVec(q.line_origin);
  r.line_dir = FromVec(q.line_dir);
  return r;
}

double DistanceToCameraLine(const LineConfig& c, double v) {
  V3 d = c.origin + v * c.dir - c.line_origin;
  V3 w = Unit(c.line_dir);
  return Norm(d - Dot(d, w) * w);
}

// The VRL parameter of the lines' closest approach (NaN for parallel lines).
double ClosestV(const LineConfig& c) {
  V3 w0 = c.origin - c.line_origin;
  double a = Dot(c.dir, c.dir), b = Dot(c.dir, c.line_dir), cc = Dot(c.line_dir, c.line_dir);
  double d = Dot(c.dir, w0), e = Dot(c.line_dir, w0), den = a * cc - b * b;
  return den > 1e-300 ? (b * e - cc * d) / den : std::nan("");
}

// The camera line at distance h from y(v0), making angle `angle` with the VRL.
LineConfig MakeLines(std::string name, double tmin, double tmax, double v0, double h, double angle) {
  LineConfig c;
  c.name = std::move(name);
  c.origin = {0.2, -0.4, 0.9};
  c.dir = Unit(V3{0.3, 1, 0.2});
  c.tmin = tmin;
  c.tmax = tmax;
  V3 n = Unit(Cross(c.dir, V3{1, 0, 0}));
  V3 m = Cross(c.dir, n);
  c.line_dir = Unit(std::cos(angle) * c.dir + std::sin(angle) * m);
  c.line_origin = c.origin + v0 * c.dir + h * n + 0.8 * c.line_dir;
  return c;
}

std::vector<LineConfig> LineConfigs() {
  std::vector<LineConfig> out;
  std::mt19937_64 rng(0x11e5);
  std::uniform_real_distribution<double> uni(0, 1);
  for (int i = 0; i < 30; ++i) {
    LineConfig c;
    c.name = "random #" + std::to_string(i);
    c.origin = {4 * uni(rng) - 2, 4 * uni(rng) - 2, 4 * uni(rng) - 2};
    c.dir = RandomUnit(rng);
    c.tmin = 0;
    c.tmax = LogUniform(rng, 0.1, 10);
    V3 w = RandomUnit(rng);
    V3 n = Cross(c.dir, w);
    if (Norm(n) < 1e-3) continue;
    double v_star = (2 * uni(rng) - 0.5) * c.tmax;
    c.line_dir = w;
    c.line_origin = c.origin + v_star * c.dir + LogUniform(rng, 0.05, 5) * Unit(n) + (4 * uni(rng) - 2) * w;
    out.push_back(c);
  }
  out.push_back(MakeLines("closest point inside", 0, 3, 1.2, 0.3, 1.0));
  out.push_back(MakeLines("closest point at tmin", 0, 3, 0, 0.05, 1.3));
  out.push_back(MakeLines("closest point far outside", 0, 3, -50, 0.5, 0.7));
  out.push_back(MakeLines("tiny h", 0, 3, 1.1, 1e-4, 1.2));
  out.push_back(MakeLines("long VRL", 0, 1000, 400, 0.3, 0.9));
  out.push_back(MakeLines("negative tmin", -2, 3, 0.5, 0.4, 1.4));
  out.push_back(MakeLines("near-parallel 1e-3", 0, 5, 2, 0.3, 1e-3));
  out.push_back(MakeLines("near-parallel 1e-6", 0, 5, 2, 0.3, 1e-6));
  out.push_back(MakeLines("parallel", 0, 5, 2, 0.7, 0));
  return out;
}

template <typename Real>
void CheckVrlPoint(const LineConfig& wanted, std::uint64_t seed) {
  using S = vrlis::VrlPoint<Real>;
  const std::string label = Label<S>();
  Summary& summary = Summary::Get();
  const LineConfig c = LineAsSeenBy<Real>(wanted);
  INFO(label << " on " << c.name);
  const S s(ToPointQuery<Real>(c));
  REQUIRE(s.valid());
  const double v0 = ClosestV(c);
  const bool parallel = !std::isfinite(v0) || std::abs(v0) > 1e12;
  std::vector<double> features;
  if (!parallel && v0 > c.tmin && v0 < c.tmax) features.push_back(v0);
  auto pdf = [&](double v) { return double(s.pdf(Real(v))); };
  auto identity = [](double v) { return v; };

  // The pdf integrates to one and is proportional to 1 / distance to the camera line.
  const std::vector<double> edges = RefinedGrid(c.tmin, c.tmax, features);
  const double mass = Sum(CellIntegrals(pdf, edges, Tolerance<Real>::quadrature));
  summary.Max(label, "normalisation_error", std::abs(mass - 1), c.name);
  CHECK(std::abs(mass - 1) <= Tolerance<Real>::normalisation);
  const double z = Sum(CellIntegrals([&](double v) { return 1 / DistanceToCameraLine(c, v); }, edges));
  double worst_shape = 0;
  for (int i = 0; i <= 256; ++i) {
    Real v = Real(c.tmin + (c.tmax - c.tmin) * i / 256);
    double expected = 1 / (DistanceToCameraLine(c, double(v)) * z);
    worst_shape = std::max(worst_shape, std::abs(double(s.pdf(v)) / expected - 1));
  }
  summary.Max(label, "relative_error_against_inverse_distance", worst_shape, c.name);
  INFO("worst relative difference from 1 / distance normalised: " << worst_shape);
  // The library floors h at the inputs' rounding noise and Real rounds the geometry:
  // relative agreement to a few thousand ulps of the inputs' scale.
  CHECK(worst_shape <= 1e4 * double(std::numeric_limits<Real>::epsilon()) * (1 + c.tmax - c.tmin));

  // Samples: finite, in range; round trip; chi-square; derivative.
  const std::vector<Real> u = UniformNumbers<Real>(seed, kSamples);
  std::vector<double> v(u.size());
  long out_of_range = 0, bad_pdf = 0;
  double worst_round_trip = 0;
  const double eps = std::numeric_limits<Real>::epsilon();
  long round_trip_failures = 0, fused_failures = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    Real vi = s.sample(u[i]);
    Real pi = s.pdf(vi);
    Real back = s.invert(vi);
    if (!(std::isfinite(vi) && vi >= Real(c.tmin) && vi <= Real(c.tmax))) ++out_of_range;
    if (!(std::isfinite(pi) && pi > 0)) ++bad_pdf;
    v[i] = double(vi);
    double err = std::abs(double(back) - double(u[i]));
    worst_round_trip = std::max(worst_round_trip, err);
    // Rounding budget: v is rounded relative to |v| and the endpoints, moving u by pdf dv.
    double budget = 16 * eps * (1 + double(pi) * (std::abs(v[i]) + std::abs(c.tmin) + std::abs(c.tmax)));
    if (!(err <= std::max(budget, Tolerance<Real>::round_trip))) ++round_trip_failures;
    if (parallel && !(std::abs(double(pi) * (c.tmax - c.tmin) - 1) <= 4 * eps)) ++bad_pdf;  // uniform
    // sample_pdf: the same v, and pdf(v) up to the rounding of v.
    vrlis::SegmentSample<Real> f = s.sample_pdf(u[i]);
    auto range = RangeAround([&](double x) { return double(s.pdf(Real(x))); }, v[i],
                             8 * eps * (std::abs(v[i]) + std::abs(c.tmin) + std::abs(c.tmax)), c.tmin, c.tmax);
    if (!(f.t == vi) || !FusedPdfAgrees(f.pdf, range)) ++fused_failures;
  }
  CHECK(fused_failures == 0);
  CHECK(out_of_range == 0);
  CHECK(bad_pdf == 0);
  summary.Max(label, "round_trip_error", worst_round_trip, c.name);
  INFO("worst round trip " << worst_round_trip);
  CHECK(round_trip_failures == 0);
  CHECK(s.invert(Real(c.tmin)) == Real(0));
  CHECK(s.invert(Real(c.tmax)) >= 1 - 4 * eps);

  ChiSquare chi = BinnedChiSquare<Real>(pdf, identity, c.tmin, c.tmax, features, v);
  summary.Count("all", "chi_square_tests");
  summary.Max(label, "chi_square", chi.statistic,
              "dof=" + std::to_string(chi.dof) + " p=" + std::to_string(chi.p_value) + " " + c.name);
  INFO("chi-square " << chi.statistic << " dof " << chi.dof << " p " << chi.p_value);
  CHECK(chi.Passes());

  std::vector<double> probe(v.begin(), v.begin() + 400);
  double scale = parallel ? c.tmax - c.tmin : std::max(DistanceToCameraLine(c, v0), 1e-9);
  DerivativeCheck d = CheckDerivative(s, parallel ? c.tmin : v0, scale, c.tmin, c.tmax, probe,
                                     std::abs(c.tmin) + std::abs(c.tmax) + Norm(c.line_origin - c.origin));
  summary.Max(label, "derivative_relative_error", d.worst_relative, c.name);
  INFO("derivative: checked " << d.checked << " skipped " << d.skipped << " failed " << d.failed << " "
                              << d.worst_note);
  CHECK(d.failed == 0);
  CHECK(d.skipped <= long(probe.size()) / 10);
}

}  // namespace

TEMPLATE_TEST_CASE("VrlPoint battery: shape, normalisation, chi-square, round trip, derivative", "[lib][vrlpoint]",
                   float, double) {
  Summary::Get().SetFile(std::string("vrlpoint-") + RealName<TestType>());
  std::uint64_t seed = 7;
  for (const LineConfig& c : LineConfigs()) CheckVrlPoint<TestType>(c, 0xda3e39cb94b95bdbull * seed++);
}

TEMPLATE_TEST_CASE("VrlPoint on intersecting lines: finite, in range, invertible", "[lib][vrlpoint]", float, double) {
  using Real = TestType;
  for (double v_cross : {0.0, 1.3, 3.0}) {
    LineConfig c = MakeLines("intersecting", 0, 3, v_cross, 0, 0.8);
    INFO("crossing at v = " << v_cross);
    vrlis::VrlPoint<Real> s(ToPointQuery<Real>(c));
    REQUIRE(s.valid());
    long bad = 0, not_increasing = 0;
    Real previous = Real(c.tmin);
    for (int i = 0; i <= 4096; ++i) {
      Real u = Real(i) / 4096;
      Real t = s.sample(u);
      if (!(std::isfinite(t) && t >= Real(c.tmin) && t <= Real(c.tmax))) ++bad;
      if (!(std::isfinite(s.pdf(t)) && s.pdf(t) >= 0 && std::isfinite(s.invert(t)))) ++bad;
      if (t < previous) ++not_increasing;
      previous = t;
    }
    CHECK(bad == 0);
    CHECK(not_increasing == 0);
  }
}

TEMPLATE_TEST_CASE("VrlPoint: sample_pdf on a zero-length VRL and on invalid input", "[lib][vrlpoint][fused]", float,
                   double) {
  using Real = TestType;
  LineConfig c = MakeLines("zero length", 1, 1, 0.5, 0.3, 1.0);
  vrlis::VrlPoint<Real> point(ToPointQuery<Real>(c));
  REQUIRE(point.valid());
  CHECK(point.sample_pdf(Real(0.5)).t == Real(1));
  CHECK(point.sample_pdf(Real(0.5)).pdf == 0);
  c.tmax = 0;  // reversed
  vrlis::VrlPoint<Real> reversed(ToPointQuery<Real>(c));
  REQUIRE_FALSE(reversed.valid());
  CHECK(std::isnan(reversed.sample_pdf(Real(0.5)).t));
  CHECK(reversed.sample_pdf(Real(0.5)).pdf == 0);
}
