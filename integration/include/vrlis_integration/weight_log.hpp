#pragma once
// The weights of the VRL gather samples a render takes, for their tails in docs/stability.md
// (vrl_compare --gather-weights): the largest effort weight 1 / q (roulette raises it, the
// floor bounds it: vrlis/effort/policy.hpp), how many samples had a weight that is not
// finite, and the distribution of the samples' contributions to their pixel, in bins of 1/128
// of an octave, so that a quantile costs no memory per sample. Header-only and lock-free;
// recording draws no random numbers, so the image is unchanged.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace vrlis::integration {

class WeightLog {
 public:
  WeightLog() : bins_(kBins) {}

  // One sample taken: its effort weight, its weight f / pdf (vrlis::GatherSample::weight) and
  // its contribution to the pixel, as the image adds it (RMS of RGB, the effort weight included).
  void Record(float effort_weight, float weight, float contribution) {
    samples_.fetch_add(1, std::memory_order_relaxed);
    if (!std::isfinite(effort_weight) || !std::isfinite(weight) || !std::isfinite(contribution)) {
      non_finite_.fetch_add(1, std::memory_order_relaxed);
      return;
    }
    Raise(largest_effort_weight_, effort_weight);
    Raise(largest_contribution_, contribution);
    bins_[Bin(contribution)].fetch_add(1, std::memory_order_relaxed);
  }

  std::uint64_t samples() const { return samples_.load(); }
  std::uint64_t non_finite() const { return non_finite_.load(); }
  float largest_effort_weight() const { return largest_effort_weight_.load(); }
  float largest_contribution() const { return largest_contribution_.load(); }

  // The p-quantile (p in [0, 1]) of the finite samples' contributions, rounded up to its
  // bin's upper edge (at most 0.8% high); 0 without samples.
  float Quantile(double p) const {
    std::uint64_t total = 0;
    for (const auto& b : bins_) total += b.load();
    const auto rank = static_cast<std::uint64_t>(std::ceil(std::clamp(p, 0.0, 1.0) * double(total)));
    std::uint64_t below = 0;
    for (std::uint32_t i = 0; i < kBins; ++i) {
      below += bins_[i].load();
      if (below > 0 && below >= rank) return std::min(Edge(i + 1), largest_contribution());
    }
    return 0;
  }

 private:
  // A non-negative float's bin: its exponent and top 7 mantissa bits (its bits but the sign and
  // the low 16), so bins are 1/128 of an octave wide and ordered as the values.
  static constexpr std::uint32_t kBins = 1u << 15;
  static std::uint32_t Bin(float x) {
    if (!(x > 0)) return 0;
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return bits >> 16;
  }
  static float Edge(std::uint32_t bin) {  // the smallest value of the bin
    const std::uint32_t bits = bin << 16;
    float x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }
  static void Raise(std::atomic<float>& largest, float x) {
    float seen = largest.load(std::memory_order_relaxed);
    while (x > seen && !largest.compare_exchange_weak(seen, x, std::memory_order_relaxed)) {
    }
  }

  std::atomic<std::uint64_t> samples_{0}, non_finite_{0};
  std::atomic<float> largest_effort_weight_{0}, largest_contribution_{0};
  std::vector<std::atomic<std::uint64_t>> bins_;
};

}  // namespace vrlis::integration
