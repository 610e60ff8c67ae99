// The samplers under attack: every camera-segment sampler and VrlPoint, in float
// and double, on the hard cases of reference.hpp and on random queries built from special
// values, against the contract written in angle/segment_sampler.hpp and vrl_point.hpp.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include <vrlis/core/running_moments.hpp>

#include "sampler_types.hpp"
#include "contract.hpp"
#include "reference.hpp"

using namespace vrlis::stability;

namespace {

// Calls f(Tag<Sampler>, name, pointwise_round_trip) for every camera-segment sampler of the
// library's registry.
template <typename Real, typename F>
void ForEachSampler(F&& f) {
  vrlis::test::ForEachSegmentSampler<Real>([&](auto tag) {
    using S = typename decltype(tag)::type;
    f(tag, vrlis::test::SamplerName<S>().c_str(), vrlis::test::RoundTripsPointwise<S>());
  });
}

// The u values every check visits: the ends, values next to them, and a stratified grid.
std::vector<double> Us(int n) {
  std::vector<double> us = {0, 1e-30, 1e-12, 1e-7, 0.25, 0.5, 0.75, 1 - 1e-7, 1 - 1e-12, std::nextafter(1.0, 0.0), 1};
  for (int i = 0; i < n; ++i) us.push_back((i + 0.5) / n);
  return us;
}

}  // namespace

TEMPLATE_TEST_CASE("invalid queries give the documented outcome", "[stability]", float, double) {
  using Real = TestType;
  const Real nan = std::numeric_limits<Real>::quiet_NaN(), inf = std::numeric_limits<Real>::infinity();
  using Q = vrlis::SegmentQuery<Real>;
  struct Bad {
    const char* what;
    void (*mutate)(Q&, Real, Real);
    vrlis::QueryError expected;
  };
  const Bad bad[] = {
      {"NaN origin", [](Q& q, Real n, Real) { q.origin.y = n; }, vrlis::QueryError::NonFinite},
      {"inf origin", [](Q& q, Real, Real i) { q.origin.x = -i; }, vrlis::QueryError::NonFinite},
      {"NaN dir", [](Q& q, Real n, Real) { q.dir.x = n; }, vrlis::QueryError::NonFinite},
      {"NaN point", [](Q& q, Real n, Real) { q.point.z = n; }, vrlis::QueryError::NonFinite},
      {"inf point", [](Q& q, Real, Real i) { q.point.x = i; }, vrlis::QueryError::NonFinite},
      {"NaN axis", [](Q& q, Real n, Real) { q.lobe.axis.x = n; }, vrlis::QueryError::NonFinite},
      {"NaN tmin", [](Q& q, Real n, Real) { q.tmin = n; }, vrlis::QueryError::NonFinite},
      {"-inf tmin", [](Q& q, Real, Real i) { q.tmin = -i; }, vrlis::QueryError::NonFinite},
      {"NaN tmax", [](Q& q, Real n, Real) { q.tmax = n; }, vrlis::QueryError::NonFinite},
      {"NaN sigma_t", [](Q& q, Real n, Real) { q.sigma_t = n; }, vrlis::QueryError::NonFinite},
      {"inf sigma_t", [](Q& q, Real, Real i) { q.sigma_t = i; }, vrlis::QueryError::NonFinite},
      {"zero dir", [](Q& q, Real, Real) { q.dir = {0, 0, 0}; }, vrlis::QueryError::NotUnitDirection},
      {"dir of length 2", [](Q& q, Real, Real) { q.dir = {2, 0, 0}; }, vrlis::QueryError::NotUnitDirection},
      {"zero axis", [](Q& q, Real, Real) { q.lobe.axis = {0, 0, 0}; }, vrlis::QueryError::NotUnitDirection},
      {"tmax < tmin", [](Q& q, Real, Real) { q.tmax = q.tmin - Real(1e-3); }, vrlis::QueryError::ReversedSegment},
      {"-inf tmax", [](Q& q, Real, Real i) { q.tmax = -i; }, vrlis::QueryError::ReversedSegment},
      {"g = 1", [](Q& q, Real, Real) { q.g = 1; }, vrlis::QueryError::InvalidAsymmetry},
      {"g = -1", [](Q& q, Real, Real) { q.g = -1; }, vrlis::QueryError::InvalidAsymmetry},
      {"g = 1.5", [](Q& q, Real, Real) { q.g = Real(1.5); }, vrlis::QueryError::InvalidAsymmetry},
      {"g = NaN", [](Q& q, Real n, Real) { q.g = n; }, vrlis::QueryError::InvalidAsymmetry},
      {"lobe g = -1", [](Q& q, Real, Real) { q.lobe.g = -1; }, vrlis::QueryError::InvalidAsymmetry},
      {"lobe g = NaN", [](Q& q, Real n, Real) { q.lobe.g = n; }, vrlis::QueryError::InvalidAsymmetry},
      {"sigma_t < 0", [](Q& q, Real, Real) { q.sigma_t = Real(-1e-30); }, vrlis::QueryError::NegativeExtinction},
  };
  auto us = Us(16);
  for (const Bad& b : bad) {
    Q q = Cast<Real>(Base(0.9));
    b.mutate(q, nan, inf);
    INFO(b.what);
    REQUIRE(vrlis::Validate(q) == b.expected);
    ForEachSampler<Real>([&](auto tag, const char* name, bool) {
      INFO(name);
      typename decltype(tag)::type s(q);
      CHECK_FALSE(s.valid());
      CHECK(s.error() == b.expected);
      std::string msg = CheckSegmentSampler(s, q, us.data(), int(us.size()), false);
      CHECK(msg == "");
    });
  }
}

TEMPLATE_TEST_CASE("zero-length segments sample tmin with pdf 0", "[stability]", float, double) {
  using Real = TestType;
  auto us = Us(16);
  for (double at : {-1.0, 0.0, 0.5, 1.0, 3.0, 1e4}) {
    for (double offset : {0.0, 1e4}) {
      auto qd = Base(0.999);
      qd.tmin = qd.tmax = at;
      qd.origin = {offset, offset, offset};
      qd.point = qd.point + vrlis::Vec3<double>{offset, offset, offset};
      auto q = Cast<Real>(qd);
      INFO("at " << at << ", offset " << offset);
      ForEachSampler<Real>([&](auto tag, const char* name, bool) {
        INFO(name);
        typename decltype(tag)::type s(q);
        REQUIRE(s.valid());
        CHECK(s.sample(Real(0.5)) == q.tmin);
        CHECK(s.pdf(q.tmin) == 0);
        CHECK(s.invert(q.tmin) == 0);
        CHECK(CheckSegmentSampler(s, q, us.data(), int(us.size()), true) == "");
      });
    }
  }
}

TEMPLATE_TEST_CASE("hard cases: finite samples inside the segment, pdf positive where the integrand is",
                   "[stability]", float, double) {
  using Real = TestType;
  auto us = Us(4000);
  for (const HardCase& hc : HardCases()) {
    auto q = Cast<Real>(hc.q);
    INFO(hc.name);
    ForEachSampler<Real>([&](auto tag, const char* name, bool) {
      INFO(name);
      typename decltype(tag)::type s(q);
      REQUIRE(s.valid());
      CHECK(CheckSegmentSampler(s, q, us.data(), int(us.size()), false) == "");
    });
  }
}

TEMPLATE_TEST_CASE("hard cases: u within 256 eps of the CDF over 16 ulps of t and of its angle around sample(u)",
                   "[stability]", float, double) {
  using Real = TestType;
  auto us = Us(4000);
  for (const HardCase& hc : HardCases()) {
    auto q = Cast<Real>(hc.q);
    INFO(hc.name);
    ForEachSampler<Real>([&](auto tag, const char* name, bool round_trip) {
      if (!round_trip) return;  // in distribution only: below
      INFO(name);
      typename decltype(tag)::type s(q);
      CHECK(CheckSegmentSampler(s, q, us.data(), int(us.size()), true) == "");
    });
  }
}

TEMPLATE_TEST_CASE("hard cases: invert(sample(U)) is uniform where the round trip holds in distribution",
                   "[stability]", float, double) {
  using Real = TestType;
  const int n = 4000;
  for (const HardCase& hc : HardCases()) {
    auto q = Cast<Real>(hc.q);
    ForEachSampler<Real>([&](auto tag, const char* name, bool round_trip) {
      if (round_trip) return;  // pointwise: above
      INFO(name);
      typename decltype(tag)::type s(q);
      if (!(s.domain().width() >= std::numeric_limits<Real>::min())) return;  // degenerate: no distribution
      // The CDF cannot resolve more than the float grid of t allows: skip segments whose CDF
      // steps by more than 1e-3 within the round trip's reach of an end (the round-trip rule
      // covers them for the other samplers).
      if (RoundTripBandInT(s, q.tmin, q.tmin, q.tmax).hi > 1e-3 ||
          (std::isfinite(q.tmax) && 1 - RoundTripBandInT(s, q.tmax, q.tmin, q.tmax).lo > 1e-3))
        return;
      // Where the samples crowd into a few representable t (a point on or next to the line),
      // the CDF steps between neighbouring t and no t can stand for the u in between: the
      // distance may exceed ~1/n by the largest such step at a sample.
      std::vector<double> back;
      double grid_step = 0;
      const Real inf = std::numeric_limits<Real>::infinity();
      for (int i = 0; i < n; ++i) {
        Real t = s.sample(Real((i + 0.5) / n));
        back.push_back(double(s.invert(t)));
        grid_step = std::max(grid_step, double(s.invert(std::nextafter(t, inf)) - s.invert(std::nextafter(t, -inf))));
      }
      std::sort(back.begin(), back.end());
      double ks = 0;
      for (int i = 0; i < n; ++i) ks = std::max({ks, std::abs(back[i] - double(i) / n), std::abs(back[i] - double(i + 1) / n)});
      INFO(hc.name << ": Kolmogorov-Smirnov distance " << ks << ", largest CDF step over one ulp of t " << grid_step);
      CHECK(ks < 0.01 + grid_step);  // a stratified, deterministic sample: the statistic is ~1/n when the CDF is right
    });
  }
}

TEMPLATE_TEST_CASE("g = 0 reduces every sampler to equiangular", "[stability]", float, double) {
  using Real = TestType;
  const Real eps = std::numeric_limits<Real>::epsilon();
  for (auto qd : {Base(0), HardCases()[13].q, HardCases()[14].q}) {
    qd.g = 0;
    qd.lobe.g = 0;
    auto q = Cast<Real>(qd);
    vrlis::Equiangular<Real> eq(q);
    ForEachSampler<Real>([&](auto tag, const char* name, bool) {
      INFO(name << ", tmax " << qd.tmax);
      typename decltype(tag)::type s(q);
      for (int i = 0; i <= 64; ++i) {
        Real u = Real(i) / 64;
        Real t = s.sample(u);
        CHECK(std::abs(eq.invert(t) - u) <= 64 * eps);
        CHECK(std::abs(s.pdf(t) - eq.pdf(t)) <= 64 * eps * eq.pdf(t));
      }
    });
  }
}

TEST_CASE("hard cases: the mean weight f / pdf matches the integral by quadrature (double)", "[stability]") {
  const int n = 20000;
  for (const HardCase& hc : HardCases()) {
    if (!hc.integrable || !(hc.q.tmax > hc.q.tmin)) continue;
    RefQuery ref(hc.q);
    double integral = Integral(ref);
    INFO(hc.name << ": integral " << integral);
    REQUIRE(integral > 0);
    REQUIRE(std::isfinite(integral));
    ForEachSampler<double>([&](auto tag, const char* name, bool) {
      typename decltype(tag)::type s(hc.q);
      vrlis::RunningMoments weight;
      for (int i = 0; i < n; ++i) {
        double t = s.sample((i + 0.5) / n);
        weight.add(ref.f(t) / s.pdf(t) / integral);
      }
      INFO(name << ": mean weight " << weight.mean());
      CHECK(std::abs(weight.mean() - 1) < 0.02);
    });
  }
}

// The two kinds of query fuzzing found (fuzz/regressions/roundtrip-cdf-step-within-ulp-*),
// rebuilt: the density in t changes by orders of magnitude within an ulp of t, so
// invert(sample(u)) misses u by far more than pdf(t) times an ulp, and the round-trip rule
// (contract.hpp) compares u with the CDF within the reach of t's rounding instead.
namespace {

// How many u of `us` miss by more than 256 eps + 64 pdf(t) (ulp(max(|t|, |tmin|)) +
// ulp(width) / (dtheta/dt)), the rule before these findings.
template <typename Sampler, typename Real = typename Sampler::Real>
int BeyondPdfTimesUlp(const Sampler& s, const vrlis::SegmentQuery<Real>& q, const std::vector<double>& us) {
  const auto& d = s.domain();
  int beyond = 0;
  for (double u : us) {
    Real t = s.sample(Real(u));
    double ulps = double(Ulp(std::max(std::abs(t), std::abs(q.tmin)))) + double(Ulp(d.width())) / double(d.dtheta_dt(t));
    double bound = 256 * double(std::numeric_limits<Real>::epsilon()) + 64 * double(s.pdf(t)) * ulps;
    if (std::abs(double(s.invert(t)) - u) > bound) ++beyond;
  }
  return beyond;
}

}  // namespace

TEST_CASE("a CDF step within an ulp of t: the round trip holds to the CDF within t's rounding", "[stability]") {
  auto us = Us(4000);
  us.push_back(2.3283064365386963e-10);  // the finding's u (2^-32)
  SECTION("Novak, double: the point 1e-12 off the line, the fit's kink inside an ulp of t") {
    vrlis::SegmentQuery<double> q;
    q.origin = {1e4, 1e4, 1};
    q.dir = Unit(V3{2, 1, 0});
    q.tmax = 3;
    q.point = q.origin + 1.0 * q.dir + V3{0, 0, 1e-12};
    q.lobe = {vrlis::LobeKind::ClampedCosine, {1, 0, 0}, 0};
    vrlis::Novak<double> s(q);
    INFO("h " << s.domain().h());
    REQUIRE_FALSE(s.domain().on_line());
    CHECK(BeyondPdfTimesUlp(s, q, us) > 0);
    CHECK(CheckSegmentSampler(s, q, us.data(), int(us.size()), true) == "");
  }
  SECTION("CauchySum, float: the point lobe's peak (g = 0.999) narrower than an ulp of t ~ 1e6") {
    vrlis::SegmentQuery<float> q;
    q.origin = {3, -1.019979f, 1};
    q.dir = {0, 0, 1};
    q.tmin = 1;
    q.tmax = std::numeric_limits<float>::infinity();
    q.g = -1e-4f;
    q.point = {4, -1.019979f, 1000002};
    q.lobe = {vrlis::LobeKind::HenyeyGreenstein, {-0.707106769f, 0, 0.707106769f}, 0.998999894f};
    vrlis::CauchySum<float> s(q);
    CHECK(BeyondPdfTimesUlp(s, q, us) > 0);
    CHECK(CheckSegmentSampler(s, q, us.data(), int(us.size()), true) == "");
  }
}

// fuzz/regressions/cauchy-flat-lobe-subnormal-primitive: a segment 1e-30 long seen from 1e6
// away spans 1e-36 rad, 1.57 rad from the segment lobe's peak. Over it the Cauchy is constant
// to the last digit, but its primitives (~1e-42) were float subnormals with three digits, and
// the CDF was off by 1.4e-4. Left out as flat, the samplers are equiangular there.
TEST_CASE("a Cauchy lobe constant over a 1e-36 rad interval is flat, not subnormal (float)", "[stability]") {
  vrlis::SegmentQuery<float> q;
  q.origin = {-1059000, 0.5f, 1e-4f};
  q.dir = {0, 1, 0};
  q.tmax = 1e-30f;
  q.g = 0.999999881f;
  q.point = {-59000, 0.5f, 1e-4f};
  auto us = Us(4000);
  vrlis::Equiangular<float> eq(q);
  REQUIRE(eq.domain().width() < 1e-35f);
  ForEachSampler<float>([&](auto tag, const char* name, bool round_trip) {
    INFO(name);
    typename decltype(tag)::type s(q);
    CHECK(CheckSegmentSampler(s, q, us.data(), int(us.size()), round_trip) == "");
    double worst = 0;
    for (double u : us) worst = std::max(worst, std::abs(double(eq.invert(s.sample(float(u)))) - u));
    INFO("largest |equiangular CDF(sample(u)) - u| " << worst);
    CHECK(worst <= 64 * double(std::numeric_limits<float>::epsilon()));
  });
}

// A rule that accepted everything would pass the test above: it must still fail a sampler
// whose t is off the CDF's inverse by more than its rounding. Two sabotaged versions of every
// pointwise sampler, each a defect the rule is there to catch.
namespace {

enum class Sabotage { NaiveAngleMap, WarpedU };

template <typename S>
class Sabotaged {
 public:
  using Real = typename S::Real;
  Sabotaged(const vrlis::SegmentQuery<Real>& q, Sabotage how) : s_(q), how_(how) {}
  bool valid() const { return s_.valid(); }
  vrlis::QueryError error() const { return s_.error(); }
  const auto& domain() const { return s_.domain(); }
  const auto& distribution() const { return s_.distribution(); }
  Real pdf(Real t) const { return s_.pdf(t); }
  Real invert(Real t) const { return s_.invert(t); }
  Real sample(Real u) const {
    if (how_ == Sabotage::WarpedU) return s_.sample(u + Real(1e-3) * u * (1 - u));
    // t = u0 + h tan(theta): the form angle_domain.hpp avoids, which cancels where |t - u0| >> h.
    const auto& d = s_.domain();
    Real t = d.u0() + d.h() * std::tan(d.theta_a() + s_.distribution().sample(u));
    return vrlis::Clamp(t, d.tmin(), d.tmax());
  }

 private:
  S s_;
  Sabotage how_;
};

}  // namespace

TEMPLATE_TEST_CASE("the round-trip rule fails samples off the CDF's inverse", "[stability]", float, double) {
  using Real = TestType;
  vrlis::SegmentQuery<double> qd;  // the segment 1000 to 2000 times h from the foot
  qd.dir = {1, 0, 0};
  qd.tmin = 10;
  qd.tmax = 20;
  qd.g = 0.9;
  qd.point = {0, 0.01, 0};
  qd.lobe = {vrlis::LobeKind::HenyeyGreenstein, Unit(V3{0.6, -0.8, 0.1}), 0.5};
  auto q = Cast<Real>(qd);
  auto us = Us(64);
  ForEachSampler<Real>([&](auto tag, const char* name, bool round_trip) {
    if (!round_trip) return;
    using S = typename decltype(tag)::type;
    INFO(name);
    CHECK(CheckSegmentSampler(S(q), q, us.data(), int(us.size()), true) == "");
    for (Sabotage how : {Sabotage::NaiveAngleMap, Sabotage::WarpedU}) {
      std::string msg = CheckSegmentSampler(Sabotaged<S>(q, how), q, us.data(), int(us.size()), true);
      INFO((how == Sabotage::NaiveAngleMap ? "t = u0 + h tan(theta): " : "u warped by 1e-3 u (1 - u): ") << msg);
      CHECK(msg.rfind("round trip", 0) == 0);
    }
  });
}

TEMPLATE_TEST_CASE("random queries built from special values keep the contract", "[stability]", float, double) {
  using Real = TestType;
  std::mt19937_64 rng(6);
  auto pick = [&](std::initializer_list<double> xs) {
    return *(xs.begin() + std::uniform_int_distribution<size_t>(0, xs.size() - 1)(rng));
  };
  std::uniform_real_distribution<double> unit(-1, 1);
  auto us = Us(64);
  for (int iter = 0; iter < 1500; ++iter) {
    vrlis::SegmentQuery<double> qd;
    double off = pick({0, 1, -1e4, 1e4});
    qd.origin = {off, off * 0.5, -off};
    double th = unit(rng) * kPi, ph = unit(rng) * kPi;
    qd.dir = pick({0, 1}) ? V3{std::cos(th), std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph)} : V3{0, 0, 1};
    qd.tmin = pick({0, -1, 1, -1e6, 0.5});
    qd.tmax = qd.tmin + pick({0, 1e-7, 1e-6, 1, 4, 1e6, kInf});
    qd.g = pick({0, 0.999, -0.999, 1e-4, -1e-4, 0.9, -0.5});
    V3 foot = qd.origin + (qd.tmin + pick({-2, 0, 0.5, 1, 1e6}) * (std::isfinite(qd.tmax) ? qd.tmax - qd.tmin : 1)) * qd.dir;
    V3 normal = Unit(vrlis::Cross(qd.dir, V3{0.3, -0.7, 0.6}));
    qd.point = foot + pick({0, 1e-7, 1e-3, 1, 1e7}) * normal;
    int kind = int(pick({0, 1, 2}));
    double a = unit(rng) * kPi, b = unit(rng) * kPi;
    V3 axis = pick({0, 1}) ? V3{std::cos(a), std::sin(a) * std::cos(b), std::sin(a) * std::sin(b)}
                           : (pick({0, 1}) ? normal : vrlis::Cross(qd.dir, normal));
    qd.lobe = {kind == 0 ? vrlis::LobeKind::None : kind == 1 ? vrlis::LobeKind::HenyeyGreenstein : vrlis::LobeKind::ClampedCosine,
               axis, pick({0, 0.999, -0.999, 1e-4, 0.9})};
    auto q = Cast<Real>(qd);
    ForEachSampler<Real>([&](auto tag, const char* name, bool) {
      typename decltype(tag)::type s(q);
      std::string msg = CheckSegmentSampler(s, q, us.data(), int(us.size()), false);
      if (!msg.empty()) {
        INFO(name << ", query " << iter << ": origin (" << q.origin.x << ", " << q.origin.y << ", " << q.origin.z
                  << ") dir (" << q.dir.x << ", " << q.dir.y << ", " << q.dir.z << ") t [" << q.tmin << ", " << q.tmax
                  << "] g " << q.g << " point (" << q.point.x << ", " << q.point.y << ", " << q.point.z << ") lobe "
                  << int(q.lobe.kind) << " axis (" << q.lobe.axis.x << ", " << q.lobe.axis.y << ", " << q.lobe.axis.z
                  << ") g " << q.lobe.g);
        CHECK(msg == "");
      }
    });
  }
}

// ---------------------------------------------------------------------------------------
TEMPLATE_TEST_CASE("VrlPoint: invalid queries give the documented outcome", "[stability]", float, double) {
  using Real = TestType;
  const Real nan = std::numeric_limits<Real>::quiet_NaN(), inf = std::numeric_limits<Real>::infinity();
  auto us = Us(16);
  auto base = Cast<Real>(HardVrlCases()[0].q);
  std::vector<vrlis::VrlPointQuery<Real>> bad(9, base);
  bad[0].origin.x = nan;
  bad[1].dir.y = nan;
  bad[2].line_origin.z = inf;
  bad[3].line_dir.x = nan;
  bad[4].tmin = nan;
  bad[5].tmax = inf;  // unbounded VRLs are invalid: the density's tail is not normalisable
  bad[6].tmax = bad[6].tmin - 1;
  bad[7].dir = {0, 0, 0};
  bad[8].line_dir = {0, 2, 0};
  for (size_t i = 0; i < bad.size(); ++i) {
    INFO("invalid VRL query " << i);
    vrlis::VrlPoint<Real> s(bad[i]);
    CHECK_FALSE(s.valid());
    CHECK(CheckVrlPoint(s, bad[i], us.data(), int(us.size())) == "");
  }
}

TEMPLATE_TEST_CASE("VrlPoint: hard cases keep the contract", "[stability]", float, double) {
  using Real = TestType;
  auto us = Us(4000);
  for (const HardVrlCase& hc : HardVrlCases()) {
    auto q = Cast<Real>(hc.q);
    INFO(hc.name);
    vrlis::VrlPoint<Real> s(q);
    REQUIRE(s.valid());
    CHECK(CheckVrlPoint(s, q, us.data(), int(us.size())) == "");
  }
}

TEMPLATE_TEST_CASE("VrlPoint: parallel and anti-parallel lines give the uniform density", "[stability]", float, double) {
  using Real = TestType;
  for (int which : {1, 2}) {
    auto q = Cast<Real>(HardVrlCases()[which].q);
    vrlis::VrlPoint<Real> s(q);
    for (int i = 0; i <= 16; ++i) {
      Real u = Real(i) / 16;
      CHECK(s.sample(u) == Approx(q.tmin + u * (q.tmax - q.tmin)).margin(1e-6));
      CHECK(s.pdf(s.sample(u)) == Approx(1 / (q.tmax - q.tmin)));
    }
  }
}

TEST_CASE("VrlPoint: the mean weight matches the integral by quadrature (double)", "[stability]") {
  const int n = 20000;
  for (const HardVrlCase& hc : HardVrlCases()) {
    if (!hc.integrable || !(hc.q.tmax > hc.q.tmin)) continue;
    RefVrlQuery<double> ref(hc.q);
    double integral = ref.Integral();
    vrlis::VrlPoint<double> s(hc.q);
    vrlis::RunningMoments weight;
    for (int i = 0; i < n; ++i) {
      double t = s.sample((i + 0.5) / n);
      weight.add(ref.f(t) / s.pdf(t) / integral);
    }
    INFO(hc.name << ": mean weight " << weight.mean() << ", max " << weight.max());
    CHECK(std::abs(weight.mean() - 1) < 1e-3);
    CHECK(weight.max() < 1.001);  // the density is proportional to the target
  }
}
