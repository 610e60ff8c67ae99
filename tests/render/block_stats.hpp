#pragma once
// Per-block statistics of independent passes: each pass is an unbiased, independent
// estimate of the image, so the mean of a block over passes has a standard error we can
// estimate from the passes themselves.
#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <vrlis/core/running_moments.hpp>
#include <vrlis_integration/renderer.hpp>

namespace vrlis::test {

struct BlockEstimate {
  std::vector<double> mean, stderr_;  // per block (or pixel)
};

inline BlockEstimate Estimates(const std::vector<vrlis::RunningMoments>& per_block) {
  BlockEstimate e;
  for (const vrlis::RunningMoments& m : per_block) {
    e.mean.push_back(m.mean());
    e.stderr_.push_back(m.standard_error());
  }
  return e;
}

// Runs `passes` passes and averages (r + g + b) / 3 over square blocks of `block` pixels.
inline BlockEstimate EstimateBlocks(vrlis::integration::Renderer& r, int width, int height, int block,
                                    int passes, std::uint64_t seed, double scale = 1) {
  const int bx = width / block, by = height / block, nb = bx * by;
  std::vector<vrlis::RunningMoments> stats(static_cast<std::size_t>(nb));
  for (int p = 0; p < passes; ++p) {
    vrlis::integration::Film f = r.RenderPass(seed, static_cast<std::uint64_t>(p), nullptr);
    std::vector<double> b(static_cast<std::size_t>(nb));
    for (int y = 0; y < by * block; ++y)
      for (int x = 0; x < bx * block; ++x) b[static_cast<std::size_t>((y / block) * bx + x / block)] += f.at(x, y).Average();
    for (std::size_t k = 0; k < stats.size(); ++k) stats[k].add(scale * b[k] / (block * block));
  }
  return Estimates(stats);
}

struct ZSummary {
  int n = 0;
  double max_abs = 0, mean = 0, rms = 0, critical = 0;
  bool Pass() const { return max_abs < critical; }
  std::string Describe() const {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%d blocks: max|z| %.2f (critical %.2f), mean z %+.2f, rms z %.2f", n, max_abs,
                  critical, mean, rms);
    return buf;
  }
};

// Two-sided z-test per block, family-wise significance `alpha` with Bonferroni's
// correction for the number of blocks. Blocks where both estimates are exactly zero
// (nothing to see) are skipped.
inline ZSummary Compare(const std::vector<double>& a_mean, const std::vector<double>& a_se,
                        const std::vector<double>& b_mean, const std::vector<double>& b_se, double alpha = 0.01) {
  ZSummary s;
  std::vector<double> z;
  for (std::size_t k = 0; k < a_mean.size(); ++k) {
    double se = std::sqrt(a_se[k] * a_se[k] + b_se[k] * b_se[k]);
    if (a_mean[k] == 0 && b_mean[k] == 0) continue;
    z.push_back((a_mean[k] - b_mean[k]) / std::max(se, 1e-300));
  }
  s.n = static_cast<int>(z.size());
  for (double v : z) {
    s.max_abs = std::max(s.max_abs, std::abs(v));
    s.mean += v / s.n;
    s.rms += v * v / s.n;
  }
  s.rms = std::sqrt(s.rms);
  boost::math::normal normal;
  s.critical = boost::math::quantile(boost::math::complement(normal, alpha / (2.0 * std::max(s.n, 1))));
  return s;
}

inline ZSummary Compare(const BlockEstimate& a, const BlockEstimate& b, double alpha = 0.01) {
  return Compare(a.mean, a.stderr_, b.mean, b.stderr_, alpha);
}

}  // namespace vrlis::test
