#pragma once
// An RGB image of radiance (one pass), and the running sum of passes.
#include <vector>

#include "common.hpp"

namespace vrlis::integration {

struct Film {
  int width = 0, height = 0;
  std::vector<Spectrum> pixels;

  Film() = default;
  Film(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {}
  Spectrum& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  const Spectrum& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

// The mean of the passes added so far.
class Accumulator {
 public:
  Accumulator(int w, int h) : sum_(w, h) {}
  void Add(const Film& pass) {
    for (std::size_t i = 0; i < sum_.pixels.size(); ++i) sum_.pixels[i] += pass.pixels[i];
    ++passes_;
  }
  int passes() const { return passes_; }
  Film Mean() const {
    Film f = sum_;
    if (passes_ > 0)
      for (Spectrum& s : f.pixels) s *= 1.f / static_cast<float>(passes_);
    return f;
  }

 private:
  Film sum_;
  int passes_ = 0;
};

}  // namespace vrlis::integration
