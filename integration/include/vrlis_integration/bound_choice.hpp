#pragma once
// Which technique carries the medium connections, chosen per image by the price of variance
// (docs/renderer.md#bound-choice): the VRL gathers up to a geometry-term bound with the
// path-traced remainder carrying the excess (share.hpp), or, at bound 0, no light paths at all,
// the renderer then being its own path tracer. The first two passes, the pilot, give every
// candidate an interleaved share of the pixels, the same in each pilot pass; every later pass
// takes the candidate whose pixels showed the least variance times counted work. A pass's
// bounds depend on the passes before it only, so every pass stays an unbiased estimate of the
// image and a render a function of its seed (Grittmann et al. 2022 choose techniques alike from
// a pilot's moments and costs; Kollig and Keller 2004 for the bound).
#include <cstddef>
#include <optional>
#include <vector>

namespace vrlis::integration {

class BoundChoice {
 public:
  // What each candidate's pilot pixels showed: per pixel and pass, the mean variance of its
  // value and its counted work (with the light pass's share where it traces light paths).
  struct Candidate {
    float bound = 0;
    double variance = 0, work = 0;
    int pixels = 0;
    double Price() const { return variance * work; }
  };

  BoundChoice() = default;  // no candidates: inactive
  explicit BoundChoice(const std::vector<float>& bounds) {
    for (float b : bounds) candidates_.push_back({b});
  }
  bool active() const { return !candidates_.empty(); }

  // The bound of pixel (x, y) in the next pass (active only).
  float Bound(int x, int y) const {
    return candidates_[chosen_ ? *chosen_ : PilotCandidate(x, y)].bound;
  }
  // Whether the next pass traces light paths: some of its pixels take a bound above 0.
  bool LightPaths() const {
    if (chosen_) return candidates_[*chosen_].bound > 0;
    for (const Candidate& c : candidates_)
      if (c.bound > 0) return true;
    return false;
  }

  // After each pass of a width-wide image, in order: each pixel's value and counted work, and
  // the light pass's counted work, shared by the pixels that use light paths.
  void EndPass(int width, const std::vector<double>& values, const std::vector<double>& work, double light_work) {
    if (chosen_) return;
    const std::size_t n = values.size();
    const double light_share = light_work / double(n);
    if (first_.empty()) {
      first_ = values;
      for (std::size_t i = 0; i < n; ++i) {
        Candidate& c = candidates_[PilotCandidate(int(i % std::size_t(width)), int(i / std::size_t(width)))];
        c.work += work[i] + (c.bound > 0 ? light_share : 0);
        c.pixels += 1;
      }
      return;
    }
    for (std::size_t i = 0; i < n; ++i) {
      Candidate& c = candidates_[PilotCandidate(int(i % std::size_t(width)), int(i / std::size_t(width)))];
      const double d = values[i] - first_[i];
      c.variance += d * d / 2;  // the pixel's variance, unbiased from two independent passes
      c.work += work[i] + (c.bound > 0 ? light_share : 0);
    }
    std::size_t best = 0;
    for (std::size_t k = 0; k < candidates_.size(); ++k) {
      Candidate& c = candidates_[k];
      if (c.pixels > 0) c.variance /= c.pixels, c.work /= 2.0 * c.pixels;
      if (c.pixels > 0 && (candidates_[best].pixels == 0 || c.Price() < candidates_[best].Price())) best = k;
    }
    chosen_ = best;
    first_.clear();
  }

  // The chosen candidate, once the pilot is over.
  std::optional<float> chosen() const {
    return chosen_ ? std::optional<float>(candidates_[*chosen_].bound) : std::nullopt;
  }
  const std::vector<Candidate>& candidates() const { return candidates_; }

 private:
  // Candidates interleaved over the image, shifted by two per row.
  std::size_t PilotCandidate(int x, int y) const { return std::size_t(x + 2 * y) % candidates_.size(); }

  std::vector<Candidate> candidates_;
  std::optional<std::size_t> chosen_;
  std::vector<double> first_;  // the first pilot pass's values
};

}  // namespace vrlis::integration
