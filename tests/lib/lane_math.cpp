// The vectorisable float math of core/lane_math.hpp against double (and the float samplers'
// double square root against std::sqrt), over every input the fits can pass and beyond: the
// accuracy its header states.
#include <catch2/catch.hpp>

#include <vrlis/core/lane_math.hpp>
#include <vrlis/core/math.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <utility>

TEST_CASE("SinCosLanes<float> is within 2 ulp of 1, and relative near 0", "[lib][lane_math]") {
  const double ulp = std::numeric_limits<float>::epsilon();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> wide(-100.0f, 100.0f), small(-0.785f, 0.785f);
  double worst_abs = 0, worst_rel = 0;
  for (int i = 0; i < 2000000; ++i) {
    float x = wide(rng);
    vrlis::SinCosPair<float> p = vrlis::SinCosLanes(x);
    worst_abs = std::max({worst_abs, std::abs(p.sin - std::sin(double(x))), std::abs(p.cos - std::cos(double(x)))});
    float y = std::ldexp(small(rng), -(i % 40));  // down to 1e-12: sin keeps relative accuracy
    double s = std::sin(double(y));
    if (s != 0) worst_rel = std::max(worst_rel, std::abs(vrlis::SinCosLanes(y).sin - s) / std::abs(s));
  }
  CHECK(worst_abs <= 2 * ulp);
  CHECK(worst_rel <= 2 * ulp);
  CHECK(std::isnan(vrlis::SinCosLanes(std::numeric_limits<float>::quiet_NaN()).sin));
}

// The Cauchy samplers' sines (samplers/cauchy_lobe.hpp): the nearest floats to the true values
// but in rare near-halfway cases, and in the order of x wherever the true values are.
TEST_CASE("SinCosRounded is sin and cos rounded to float, in their order", "[lib][lane_math]") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> angle(-12.6f, 12.6f);
  long differ = 0, beyond_ulp = 0;
  const int n = 2000000;
  for (int i = 0; i < n; ++i) {
    const float x = angle(rng);
    const vrlis::SinCosPair<float> p = vrlis::SinCosRounded(x);
    for (const auto& [got, want] : {std::pair<float, double>{p.sin, std::sin(double(x))}, {p.cos, std::cos(double(x))}}) {
      const float nearest = static_cast<float>(want);
      differ += got != nearest;
      beyond_ulp += got != nearest && got != std::nextafter(nearest, 2.0f) && got != std::nextafter(nearest, -2.0f);
    }
  }
  INFO(differ << " of " << 2 * n << " differ from the nearest float");
  CHECK(beyond_ulp == 0);
  CHECK(differ <= 2 * n / 100000);
  // Consecutive floats from several starts: each result moves as the true value does (or stays).
  long reversed = 0;
  for (float start : {1e-6f, 0.1f, 0.7853f, 1.5707f, 1.5708f, 3.1415f, 4.71f, 6.2831f, -2.0f}) {
    float x = start;
    vrlis::SinCosPair<float> last = vrlis::SinCosRounded(x);
    for (int i = 0; i < 200000; ++i) {
      const float next = std::nextafter(x, 100.0f);
      const vrlis::SinCosPair<float> e = vrlis::SinCosRounded(next);
      const double ds = std::sin(double(next)) - std::sin(double(x)), dc = std::cos(double(next)) - std::cos(double(x));
      reversed += (ds > 0 && e.sin < last.sin) || (ds < 0 && e.sin > last.sin);
      reversed += (dc > 0 && e.cos < last.cos) || (dc < 0 && e.cos > last.cos);
      x = next, last = e;
    }
  }
  CHECK(reversed == 0);
  CHECK(std::isnan(vrlis::SinCosRounded(std::numeric_limits<float>::quiet_NaN()).sin));
}

TEST_CASE("RsqrtLanes<float> is within 2 ulp over the normal floats", "[lib][lane_math]") {
  const double ulp = std::numeric_limits<float>::epsilon();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> mantissa(1.0f, 2.0f);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    float x = std::ldexp(mantissa(rng), i % 250 - 125);
    double exact = 1 / std::sqrt(double(x));
    worst = std::max(worst, std::abs(vrlis::RsqrtLanes(x) - exact) / exact);
  }
  CHECK(worst <= 2 * ulp);
}

// Over the normal numbers of Real at every exponent, and at 0 and infinity: within `ulps` of
// the correctly rounded std::sqrt.
template <typename Real, typename Rng>
void SqrtLanesIsWithin(double ulps, Rng& rng) {
  std::uniform_real_distribution<Real> mantissa(1, 2);
  const int exponents = std::numeric_limits<Real>::max_exponent - std::numeric_limits<Real>::min_exponent;
  double worst = 0;
  auto take = [&](Real x) {
    const Real exact = std::sqrt(x);
    const Real ulp = std::nextafter(exact, std::numeric_limits<Real>::infinity()) - exact;
    worst = std::max(worst, double(std::abs(vrlis::SqrtLanes(x) - exact) / ulp));
  };
  for (int i = 0; i < 2000000; ++i)
    take(std::ldexp(mantissa(rng), std::numeric_limits<Real>::min_exponent - 1 + i % exponents));
  take(std::numeric_limits<Real>::min());
  take(std::numeric_limits<Real>::max());
  CHECK(worst <= ulps);
  CHECK(vrlis::SqrtLanes(Real(0)) == 0);
  CHECK(vrlis::SqrtLanes(std::numeric_limits<Real>::infinity()) == std::numeric_limits<Real>::infinity());
}

TEST_CASE("SqrtLanes is within 3 ulp (float) and 1 ulp (double) over the normal numbers", "[lib][lane_math]") {
  std::mt19937 rng(13);
  SqrtLanesIsWithin<float>(3, rng);
  SqrtLanesIsWithin<double>(1, rng);
}

TEST_CASE("SelectLanes picks either operand bit for bit (float and double)", "[lib][lane_math]") {
  constexpr float kInf = std::numeric_limits<float>::infinity(), kTiny = std::numeric_limits<float>::denorm_min();
  for (float a : {0.0f, -0.0f, 1.5f, -kInf, kTiny}) {
    CHECK(std::signbit(vrlis::SelectLanes(true, a, 2.0f)) == std::signbit(a));
    CHECK(vrlis::SelectLanes(true, a, 2.0f) == a);
    CHECK(vrlis::SelectLanes(false, 2.0f, a) == a);
    const double d = a;
    CHECK(std::signbit(vrlis::SelectLanes(true, d, 2.0)) == std::signbit(d));
    CHECK(vrlis::SelectLanes(true, d, 2.0) == d);
    CHECK(vrlis::SelectLanes(false, 2.0, d) == d);
  }
  CHECK(std::isnan(vrlis::SelectLanes(true, std::nan(""), 1.0)));
}

TEST_CASE("The lanes' Accuracy::Fit is within 1e-4 relative (sine and cosine: of 1, and relative near 0)",
          "[lib][lane_math]") {
  using vrlis::Accuracy;
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> wide(-100.0f, 100.0f), small(-0.785f, 0.785f), mantissa(1.0f, 2.0f),
      range(-87.3f, 88.0f);
  double sincos = 0, sin_near_0 = 0, rsqrt = 0, exp = 0;
  for (int i = 0; i < 1000000; ++i) {
    float x = wide(rng);
    vrlis::SinCosPair<float> p = vrlis::SinCosLanes<Accuracy::Fit>(x);
    sincos = std::max({sincos, std::abs(p.sin - std::sin(double(x))), std::abs(p.cos - std::cos(double(x)))});
    float y = std::ldexp(small(rng), -(i % 40));
    sin_near_0 = std::max(sin_near_0, std::abs(vrlis::SinCosLanes<Accuracy::Fit>(y).sin / std::sin(double(y)) - 1));
    float z = std::ldexp(mantissa(rng), i % 250 - 125);
    rsqrt = std::max(rsqrt, std::abs(vrlis::RsqrtLanes<Accuracy::Fit>(z) * std::sqrt(double(z)) - 1));
    float e = range(rng);
    exp = std::max(exp, std::abs(vrlis::ExpLanes<Accuracy::Fit>(e) / std::exp(double(e)) - 1));
  }
  CHECK(sincos <= 1e-4);
  CHECK(sin_near_0 <= 1e-4);
  CHECK(rsqrt <= 1e-4);
  CHECK(exp <= 1e-4);
}

namespace {
// |got - exact| in units of the float ulp at exact (exact from double).
double FloatUlps(float got, double exact) {
  if (exact == 0) return got == 0 ? 0 : std::numeric_limits<double>::infinity();
  return std::abs(got - exact) / std::ldexp(1.0, std::ilogb(exact) - 23);
}
}  // namespace

TEST_CASE("CbrtLanes<float> is within 2.5e-5 relative over the normal floats", "[lib][lane_math]") {
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> mantissa(1.0f, 2.0f);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    float x = std::ldexp(mantissa(rng), i % 250 - 125);
    double exact = std::cbrt(double(x));
    worst = std::max(worst, std::abs(vrlis::CbrtLanes(x) - exact) / exact);
  }
  CHECK(worst <= 2.5e-5);
}

TEST_CASE("Log1pLanes<float> is within 1 ulp from -1 to float's largest, and keeps its special values",
          "[lib][lane_math]") {
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> mantissa(1.0f, 2.0f);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    // Magnitudes 2^-150 .. 2^127 of either sign, negative ones inside (-1, 0).
    float x = std::ldexp(mantissa(rng), i % 278 - 150);
    if (i & 1) x = x < 1 ? -x : -std::ldexp(mantissa(rng), -1 - i % 30);
    worst = std::max(worst, FloatUlps(vrlis::Log1pLanes(x), std::log1p(double(x))));
  }
  CHECK(worst <= 1);
  const float inf = std::numeric_limits<float>::infinity();
  CHECK(vrlis::Log1pLanes(-1.0f) == -inf);
  CHECK(std::isnan(vrlis::Log1pLanes(-1.5f)));
  CHECK(vrlis::Log1pLanes(inf) == inf);
  CHECK(std::isnan(vrlis::Log1pLanes(std::numeric_limits<float>::quiet_NaN())));
  CHECK(vrlis::Log1pLanes(1e-40f) == 1e-40f);  // subnormal: log1p(x) = x
}

TEST_CASE("Expm1Lanes<float> is within 2 ulp over its finite range, relative for tiny x, and saturates",
          "[lib][lane_math]") {
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> wide(-25.0f, 88.72f), mantissa(1.0f, 2.0f);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    float x = i % 3 ? wide(rng) : std::ldexp(mantissa(rng), i % 150 - 150) * (i & 1 ? -1.0f : 1.0f);  // below 1 in magnitude
    worst = std::max(worst, FloatUlps(vrlis::Expm1Lanes(x), std::expm1(double(x))));
  }
  CHECK(worst <= 2);
  const float inf = std::numeric_limits<float>::infinity();
  CHECK(vrlis::Expm1Lanes(89.0f) == inf);
  CHECK(vrlis::Expm1Lanes(inf) == inf);
  CHECK(vrlis::Expm1Lanes(-inf) == -1);
  CHECK(vrlis::Expm1Lanes(-30.0f) == -1);
  CHECK(std::isnan(vrlis::Expm1Lanes(std::numeric_limits<float>::quiet_NaN())));
}

TEST_CASE("ExpLanes<float> is within 2 ulp down to the smallest normal result, 0 below", "[lib][lane_math]") {
  const double ulp = std::numeric_limits<float>::epsilon();
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> range(-87.3f, 88.0f), small(-1.0f, 1.0f);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    float x = i % 2 ? range(rng) : std::ldexp(small(rng), -(i % 30));
    double exact = std::exp(double(x));
    worst = std::max(worst, std::abs(vrlis::ExpLanes(x) - exact) / exact);
  }
  CHECK(worst <= 2 * ulp);
  CHECK(vrlis::ExpLanes(0.0f) == 1.0f);
  CHECK(vrlis::ExpLanes(-90.0f) == 0.0f);
  CHECK(vrlis::ExpLanes(-std::numeric_limits<float>::infinity()) == 0.0f);
  CHECK(std::isnan(vrlis::ExpLanes(std::numeric_limits<float>::quiet_NaN())));
}

TEST_CASE("Atan2Lanes<float> is within 3 ulp, relative, over every octant and scale", "[lib][lane_math]") {
  const double ulp = std::numeric_limits<float>::epsilon();
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> mantissa(-1.0f, 1.0f);
  double worst = 0;
  for (int i = 0; i < 2000000; ++i) {
    // Ratios |y / x| from 2^-60 to 2^60, both signs: every octant, small results included.
    float y = std::ldexp(mantissa(rng), i % 61 - 30), x = std::ldexp(mantissa(rng), (i / 61) % 61 - 30);
    double exact = std::atan2(double(y), double(x));
    if (exact != 0) worst = std::max(worst, std::abs(vrlis::Atan2Lanes(y, x) - exact) / std::abs(exact));
  }
  CHECK(worst <= 3 * ulp);
  CHECK(vrlis::Atan2Lanes(0.0f, 0.0f) == 0);
  CHECK(vrlis::Atan2Lanes(0.0f, -1.0f) == 3.1415927f);
  CHECK(std::isnan(vrlis::Atan2Lanes(std::numeric_limits<float>::quiet_NaN(), 1.0f)));
  CHECK(std::isnan(vrlis::Atan2Lanes(1.0f, std::numeric_limits<float>::quiet_NaN())));
}
