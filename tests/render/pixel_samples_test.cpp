// Stratified pixel samples: each pass's point is uniform in its pixel, the passes of one
// pixel are a (0,2)-sequence, and in the room scene the stratified image is unbiased and
// has a lower error at the beam stripes' edges than independent samples at the same passes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <vrlis_integration/pixel_samples.hpp>
#include <vrlis_scenes/scenes.hpp>

#include "block_stats.hpp"
#include "stats.hpp"  // tests/support: Pearson's chi-square
#include "uncontrolled.hpp"

namespace {

using vrlis::integration::PixelPoint;

// Pearson's test of points against the uniform density on [0, 1)^2, over 16 x 16 bins.
vrlis::test::ChiSquare UniformInPixel(const std::vector<PixelPoint>& points) {
  const int n = 16;
  std::vector<long> counts(n * n, 0);
  for (PixelPoint p : points) ++counts[static_cast<std::size_t>(int(p.y * n) * n + int(p.x * n))];
  return vrlis::test::PearsonTest(counts, std::vector<double>(counts.size(), 1.0), static_cast<long>(points.size()));
}

// Whether 2^k points fall one in each cell of every elementary partition of [0, 1)^2 into
// 2^a x 2^(k-a) cells, a = 0..k: the (0,k,2)-net property.
bool IsZeroNet(const std::vector<PixelPoint>& points, int k) {
  for (int a = 0; a <= k; ++a) {
    std::vector<int> hits(std::size_t{1} << k, 0);
    for (PixelPoint p : points) {
      int cx = static_cast<int>(p.x * (1 << a)), cy = static_cast<int>(p.y * (1 << (k - a)));
      if (++hits[static_cast<std::size_t>(cy * (1 << a) + cx)] > 1) return false;
    }
  }
  return true;
}

std::vector<PixelPoint> Stratified(std::uint64_t seed, std::uint64_t pixel, std::uint64_t first, std::uint64_t count) {
  std::vector<PixelPoint> p;
  for (std::uint64_t i = first; i < first + count; ++i) p.push_back(vrlis::integration::StratifiedPixelPoint(seed, pixel, i));
  return p;
}

}  // namespace

TEST_CASE("stratified pixel samples: each pass uniform in the pixel", "[render][pixel-samples]") {
  for (std::uint64_t pass : {0, 1, 5, 37}) {
    std::vector<PixelPoint> points;
    for (std::uint64_t pixel = 0; pixel < 65536; ++pixel) points.push_back(vrlis::integration::StratifiedPixelPoint(4, pixel, pass));
    vrlis::test::ChiSquare chi = UniformInPixel(points);
    std::printf("[render] stratified pixel samples, pass %d over 65536 pixels: chi2 %.1f (dof %d), p %.3g\n",
                int(pass), chi.statistic, chi.dof, chi.p_value);
    CHECK(chi.Passes());
  }
  // Control: one point per pixel reused, as with no scramble, is far from uniform.
  std::vector<PixelPoint> unscrambled(65536, vrlis::integration::StratifiedPixelPoint(4, 0, 5));
  CHECK_FALSE(UniformInPixel(unscrambled).Passes());
}

TEST_CASE("stratified pixel samples: a pixel's passes form (0,k,2)-nets", "[render][pixel-samples]") {
  for (std::uint64_t pixel = 0; pixel < 64; ++pixel) {
    INFO("pixel " << pixel);
    CHECK(IsZeroNet(Stratified(4, pixel, 0, 16), 4));
    CHECK(IsZeroNet(Stratified(4, pixel, 16, 16), 4));  // the next 16 too: a (0,2)-sequence
    CHECK(IsZeroNet(Stratified(4, pixel, 0, 256), 8));
  }
  // Control: 16 independent points are not a net (probability 16! / 16^16 per partition).
  std::vector<PixelPoint> independent;
  vrlis::integration::Rng rng(4, 0, 0, vrlis::integration::StreamPurpose::Camera);
  for (int i = 0; i < 16; ++i) independent.push_back({rng.Uniform(), rng.Uniform()});
  CHECK_FALSE(IsZeroNet(independent, 4));
}

// The room at 32 x 32: most of its per-pass variance is the jitter crossing the hard edges of
// the beam stripes on the floor, which stratification across passes averages out faster.
TEST_CASE("stratified pixel samples: room unbiased, lower error at the stripes' edges", "[render][pixel-samples]") {
  auto built = vrlis::scenes::BuildScene("room", {});
  REQUIRE(built);
  vrlis::integration::RenderSettings s;
  s.width = s.height = 32;
  s.vrls_per_pass = 4;
  s.transport = vrlis::test::Uncontrolled(built->transport);
  const int block = 8, direct_passes = 2048, passes = 128, reference_passes = 512;
  // The mean image of n passes, and the mean of each block with its standard error.
  auto render = [&](vrlis::integration::PixelSamples kind, std::uint64_t seed, int n, vrlis::test::BlockEstimate* blocks) {
    s.pixel_samples = kind;
    vrlis::integration::VrlRenderer r(built->scene, s);
    vrlis::integration::Accumulator acc(s.width, s.height);
    const int bx = s.width / block;
    std::vector<vrlis::RunningMoments> stats(static_cast<std::size_t>(bx * (s.height / block)));
    for (int p = 0; p < n; ++p) {
      vrlis::integration::Film f = r.RenderPass(seed, static_cast<std::uint64_t>(p), nullptr);
      std::vector<double> b(stats.size());
      for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) b[static_cast<std::size_t>((y / block) * bx + x / block)] += f.at(x, y).Average();
      for (std::size_t k = 0; k < stats.size(); ++k) stats[k].add(b[k] / (block * block));
      acc.Add(f);
    }
    if (blocks) *blocks = vrlis::test::Estimates(stats);
    return acc.Mean();
  };
  using vrlis::integration::PixelSamples;

  // Unbiased: block means agree. The kinds of sample differ in the camera ray alone, so the
  // direct light, whose noise is the jitter's, tests them with power that the VRL noise of
  // the whole transport would drown. The stratified passes are not independent; for a
  // scrambled (0,m,2)-net in base 2 the variance of the mean is at most twice that of
  // independent points (Owen, "Monte Carlo variance of scrambled net quadrature", 1997), so
  // its standard error from the pass spread is taken twice in variance: conservative.
  s.transport.medium_to_medium = s.transport.medium_to_surface = s.transport.indirect = false;
  s.transport.surface_to_surface = s.transport.surface_to_medium = false;
  vrlis::test::BlockEstimate independent_blocks, stratified_blocks;
  render(PixelSamples::Independent, 1, direct_passes, &independent_blocks);
  render(PixelSamples::Stratified, 1, direct_passes, &stratified_blocks);
  for (double& se : stratified_blocks.stderr_) se *= std::sqrt(2.0);
  vrlis::test::ZSummary z = vrlis::test::Compare(stratified_blocks, independent_blocks);
  std::printf("[render] room direct light, stratified vs independent block means: %s\n", z.Describe().c_str());
  CHECK(z.Pass());
  for (double& m : stratified_blocks.mean) m *= 1.1;  // control: 10% off must be detected
  vrlis::test::ZSummary zc = vrlis::test::Compare(stratified_blocks, independent_blocks);
  std::printf("[render] room direct light, control x1.10: %s\n", zc.Describe().c_str());
  CHECK_FALSE(zc.Pass());

  s.transport = vrlis::test::Uncontrolled(built->transport);
  const vrlis::integration::Film independent = render(PixelSamples::Independent, 1, passes, nullptr);
  const vrlis::integration::Film stratified = render(PixelSamples::Stratified, 1, passes, nullptr);
  const vrlis::integration::Film reference = render(PixelSamples::Independent, 2, reference_passes, nullptr);

  // The stripes' edges: the tenth of the pixels with the largest step to a neighbour in
  // the reference.
  auto at = [&](const vrlis::integration::Film& f, int x, int y) { return double(f.at(x, y).Average()); };
  std::vector<std::pair<double, int>> steps;
  for (int y = 0; y + 1 < s.height; ++y)
    for (int x = 0; x + 1 < s.width; ++x)
      steps.push_back({std::max(std::abs(at(reference, x + 1, y) - at(reference, x, y)),
                                std::abs(at(reference, x, y + 1) - at(reference, x, y))),
                       y * s.width + x});
  std::sort(steps.rbegin(), steps.rend());
  steps.resize(steps.size() / 10);
  auto edge_rmse = [&](const vrlis::integration::Film& f) {
    double sum = 0;
    for (auto [step, i] : steps) sum += (f.pixels[std::size_t(i)] + (-1.f) * reference.pixels[std::size_t(i)]).MeanSquare();
    return std::sqrt(sum / double(steps.size()));
  };
  const double e_independent = edge_rmse(independent), e_stratified = edge_rmse(stratified);
  std::printf("[render] room, %d passes, RMSE at %zu edge pixels vs %d passes: independent %.4g, stratified %.4g (x%.2f)\n",
              passes, steps.size(), reference_passes, e_independent, e_stratified, e_stratified / e_independent);
  CHECK(e_stratified < 0.8 * e_independent);
}
