// Hypotheses: the library's price learner (vrlis/effort/price.hpp) drives the effort control of
// a renderer that only calls the one-call gather, as the README's example does:
// - the image keeps its mean: over 300 passes of a 6 x 6 image of camera segments against 12
//   VRLs whose weights span four decades, the controlled image's mean is the uncontrolled
//   one's within 4 standard errors, and with the effort weight left out of the visitor's
//   contribution (a sabotage) it is rejected;
// - it learns and acts: a price after the first pass, and gathers rouletted and split;
// - a render is a function of its seed: the same seed gives the same image bit for bit, and a
//   learner fed the same passes hands out the same settings;
// - a record with a visitor that returns nothing is rejected, not silently unlearned; so are a
//   pixel outside the image and a pass with a value short;
// - a call counts its operations at the constants of the lanes in use (core/dispatch.hpp), and
//   a visit only for a sample that contributes.
#include <catch2/catch.hpp>
#include <vrlis/effort/price.hpp>
#include <vrlis/gather/gather_vrls.hpp>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "extern_gathers.hpp"

namespace {

using Real = float;
constexpr int kSide = 6;

struct Scene {
  vrlis::Medium<Real> medium = vrlis::Medium<Real>::FromScatteringExtinction(Real(0.3), Real(0.5), Real(0.8));
  std::vector<vrlis::VrlSegment<Real>> vrls;
  std::vector<Real> power;  // also each VRL's predicted contribution: the control's weights
  vrlis::FixedSamplers<vrlis::NovakEntry> samplers;  // one pair compiled

  Scene() {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 12; ++i) {
      const vrlis::Vec3<Real> origin{Real(1 + std::abs(2 * u(rng))) * (i % 2 ? 1 : -1), Real(2 * u(rng)),
                                     Real(-1 - 3 * std::abs(u(rng)))};
      vrls.push_back({origin, vrlis::Normalize(vrlis::Vec3<Real>{Real(u(rng)), Real(u(rng)), Real(u(rng))}),
                      Real(0.5 + 2 * std::abs(u(rng)))});
      power.push_back(Real(std::pow(10.0, 2 * u(rng))));
    }
  }
  vrlis::RaySegment<Real> Camera(int x, int y) const {
    const vrlis::Vec3<Real> dir{Real(x - 2.5) / kSide, Real(y - 2.5) / kSide, -1};
    return {{0, 0, 0}, vrlis::Normalize(dir), Real(0.5), Real(6)};
  }
};

struct Render {
  std::vector<double> mean;  // per pass, of the image
  std::vector<double> last;  // the last pass's pixels
  double price = 0, samples = 0, vrls = 0;
};

// `passes` passes, the control on or off; `sabotage`: the pixel's sum leaves out the weight of
// rouletted gathers (w > 1; without split ones' too, whose w < 1 raises the mean as much as
// roulette's lowers it here), and what the visitor returns to the record keeps it: a record that
// learned from the sabotaged values could turn the decisions off, leaving no weight to leave out.
Render RenderPasses(const Scene& s, bool on, int passes, std::uint32_t seed, bool sabotage = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(0, 1);
  auto uniform = [&] { return u(rng); };
  vrlis::EffortPrice price(kSide, kSide);
  vrlis::EffortSettings control;
  control.on = on;
  Render r;
  std::vector<double> pixels(kSide * kSide);
  for (int pass = 0; pass < passes; ++pass) {
    price.BeginPass(control);
    for (int p = 0; p < kSide * kSide; ++p) {
      const vrlis::PixelEffort effort = price.Pixel(p % kSide, p / kSide, uniform);
      double sum = 0;
      vrlis::GatherMediumVrls(
          s.samplers, s.Camera(p % kSide, p / kSide), s.medium, s.vrls.data(), int(s.vrls.size()), uniform,
          [&](int i, const vrlis::GatherSample<Real>& g, Real w) {
            const double added = double(w) * g.weight * s.power[std::size_t(i)];
            sum += sabotage && w > 1 ? added / double(w) : added;
            return added;  // the record learns as without the sabotage, so the control still decides
          },
          effort.Medium(s.power.data()));
      pixels[std::size_t(p)] = sum;
      r.samples += effort.record->medium.samples, r.vrls += effort.record->medium.vrls;
    }
    price.EndPass(pixels);
    double m = 0;
    for (double v : pixels) m += v / pixels.size();
    r.mean.push_back(m);
  }
  r.last = pixels;
  r.price = price.price(vrlis::GatherKind::Medium);
  return r;
}

// The mean over the passes after the first and its standard error.
std::pair<double, double> MeanAndError(const std::vector<double>& x) {
  double sum = 0, sum_sq = 0;
  const double n = double(x.size() - 1);
  for (std::size_t k = 1; k < x.size(); ++k) sum += x[k], sum_sq += x[k] * x[k];
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum_sq / n - mean * mean) / (n - 1))};
}

}  // namespace

TEST_CASE("EffortPrice: a renderer's controlled image keeps its mean but not without 1 / q",
          "[gather][effort]") {
  const Scene s;
  const Render off = RenderPasses(s, false, 1200, 1), on = RenderPasses(s, true, 1200, 2),
               sabotaged = RenderPasses(s, true, 1200, 2, true);
  const auto [m_off, e_off] = MeanAndError(off.mean);
  const auto [m_on, e_on] = MeanAndError(on.mean);
  const auto [m_bad, e_bad] = MeanAndError(sabotaged.mean);
  const double z = (m_on - m_off) / std::hypot(e_on, e_off), z_bad = (m_bad - m_off) / std::hypot(e_bad, e_off);
  INFO("off " << m_off << " +- " << e_off << ", on " << m_on << " +- " << e_on << " (z " << z << "), sabotaged "
              << m_bad << " (z " << z_bad << "); price " << on.price << ", samples per VRL " << on.samples / on.vrls);
  CHECK(std::abs(z) < 4);
  CHECK(std::abs(z_bad) > 4);
  CHECK(on.price > 0);
  CHECK(on.samples != on.vrls);  // the control took some gathers other than once
}

TEST_CASE("EffortPrice: the same seed gives the same image, the same passes the same settings", "[gather][effort]") {
  const Scene s;
  const Render a = RenderPasses(s, true, 6, 7), b = RenderPasses(s, true, 6, 7), c = RenderPasses(s, true, 6, 8);
  CHECK(a.last == b.last);
  CHECK(a.price == b.price);
  CHECK(a.last != c.last);
}

TEST_CASE("EffortPrice: a silent visitor with a record, a pixel outside, a value short are rejected",
          "[gather][effort]") {
  const Scene s;
  vrlis::EffortRecord record;
  vrlis::EffortCall<Real> call;
  call.settings.on = true, call.record = &record;
  auto uniform = [] { return Real(0.5); };
  auto silent = [](int, const vrlis::GatherSample<Real>&, Real) {};
  CHECK_THROWS_AS(vrlis::GatherMediumVrls(s.samplers, s.Camera(0, 0), s.medium, s.vrls.data(), int(s.vrls.size()),
                                          uniform, silent, call),
                  std::invalid_argument);
  call.record = nullptr;  // without a record the same visitor is the plain gather's
  CHECK_NOTHROW(vrlis::GatherMediumVrls(s.samplers, s.Camera(0, 0), s.medium, s.vrls.data(), int(s.vrls.size()),
                                        uniform, silent, call));
  vrlis::EffortPrice price(kSide, kSide);
  price.BeginPass(call.settings);
  CHECK_THROWS_AS(price.Pixel(kSide, 0, uniform), std::out_of_range);
  CHECK_THROWS_AS(price.Pixel(0, -1, uniform), std::out_of_range);
  CHECK_NOTHROW(price.Pixel(kSide - 1, kSide - 1, uniform));
  CHECK_THROWS_AS(price.EndPass(std::vector<double>(kSide * kSide - 1)), std::invalid_argument);
  CHECK_NOTHROW(price.EndPass(std::vector<double>(kSide * kSide)));
}

TEST_CASE("Counted work: a call's is its operations' on the lanes in use, visits of contributing samples alone",
          "[gather][effort]") {
  const Scene s;
  // A surface point facing +z, and VRLs above it and below its plane: those below give
  // samples of zero weight, which need no occlusion ray.
  const vrlis::Vec3<Real> point{0, 0, 0}, normal{0, 0, 1};
  std::vector<vrlis::VrlSegment<Real>> vrls;
  for (int i = 0; i < 8; ++i)
    vrls.push_back({{Real(i - 4), Real(1), Real(i % 2 ? 1.5 : -1.5)}, vrlis::Normalize(vrlis::Vec3<Real>{1, 1, 0}), 2});
  const int n = int(vrls.size());
  for (const bool widest : {true, false}) {
    vrlis::UseWidestLanes(widest);
    INFO("widest lanes allowed " << widest << ", AVX2 in use " << vrlis::detail::Avx2LanesInUse());
    const vrlis::CountedWork& costs = vrlis::LanesWork();
    CHECK(&costs == (vrlis::detail::Avx2LanesInUse() ? &vrlis::detail::kAvx2Work : &vrlis::detail::kBuiltWork));
    vrlis::EffortRecord record;
    vrlis::EffortCall<Real> call;  // the control off: one sample per VRL, no bounds, no decisions
    call.record = &record, call.visit_work = 1000;
    int visits = 0;
    vrlis::GatherSurfaceVrls(
        s.samplers, point, normal, s.medium, vrls.data(), n, [] { return Real(0.5); },
        [&](int, const vrlis::GatherSample<Real>& g, Real) {
          visits += g.contributes();
          return double(g.weight);
        },
        call);
    REQUIRE(visits == n / 2);
    const double expected = costs.operations.vrl * (1 + n) +
                            n * costs.SurfaceSample(vrlis::SegmentSamplers::Of<vrlis::NovakEntry>()) + 1000.0 * visits;
    CHECK(record.work == Approx(expected).epsilon(1e-12));
  }
  vrlis::UseWidestLanes(true);
}
