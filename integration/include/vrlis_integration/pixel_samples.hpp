#pragma once
// Where in its pixel a pass samples: independently per pass, or stratified across the
// passes of a pixel by the first two dimensions of the Sobol sequence (a (0,2)-sequence in
// base 2), Owen-scrambled per pixel. Scrambled, every pass's point is uniform in the pixel on
// its own, and the first 2^k passes of a pixel put one point in each elementary interval
// of area 2^-k (Owen, "Randomly permuted (t,m,s)-nets and (t,s)-sequences", 1995): the mean
// over passes converges faster at the edges the jitter crosses, while each pass's
// distribution is what independent sampling gives.
#include <cstdint>

#include "common.hpp"

namespace vrlis::integration {

enum class PixelSamples { Independent, Stratified };

struct PixelPoint {
  float x = 0.5f, y = 0.5f;  // in [0, 1)^2
};

namespace pixel_samples_detail {

// Dimension 1: the van der Corput radical inverse in base 2, as 32 fraction bits.
inline std::uint32_t VanDerCorput(std::uint32_t i) {
  i = (i << 16) | (i >> 16);
  i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
  i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
  i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
  return ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
}

// Dimension 2 of Sobol: generator matrix the upper-triangular Pascal matrix mod 2, whose
// column j (bit j of the index) is v_j = v_{j-1} ^ (v_{j-1} >> 1) from v_0 = 2^31.
inline std::uint32_t SobolSecond(std::uint32_t i) {
  std::uint32_t r = 0;
  for (std::uint32_t v = 1u << 31; i; i >>= 1, v ^= v >> 1)
    if (i & 1) r ^= v;
  return r;
}

// Owen's nested uniform scramble of 32 fraction bits: bit d (from the top) is flipped by a
// random bit drawn for the node of the binary tree that the d bits above it name, so that
// points sharing their first d bits stay together (the net property survives) and each
// point is uniform.
inline std::uint32_t OwenScramble(std::uint32_t v, std::uint64_t seed) {
  std::uint32_t out = 0;
  for (int d = 0; d < 32; ++d) {
    const std::uint64_t node = (std::uint64_t{1} << d) | (d ? v >> (32 - d) : 0);  // unique per (depth, prefix)
    const std::uint32_t flip = static_cast<std::uint32_t>(SplitMix64(seed ^ SplitMix64(node)) & 1);
    out |= (((v >> (31 - d)) & 1) ^ flip) << (31 - d);
  }
  return out;
}

// The top 24 bits, exact in a float: [0, 1 - 2^-24].
inline float ToUnit(std::uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

}  // namespace pixel_samples_detail

// Point `pass` of the stratified sequence of pixel `pixel`, scrambled by (seed, pixel) alone.
inline PixelPoint StratifiedPixelPoint(std::uint64_t seed, std::uint64_t pixel, std::uint64_t pass) {
  namespace d = pixel_samples_detail;
  const std::uint64_t key = SplitMix64(seed ^ SplitMix64(pixel ^ 0x7069786c73616d70ull));
  const auto i = static_cast<std::uint32_t>(pass);  // the sequence repeats after 2^32 passes
  return {d::ToUnit(d::OwenScramble(d::VanDerCorput(i), SplitMix64(key + 1))),
          d::ToUnit(d::OwenScramble(d::SobolSecond(i), SplitMix64(key + 2)))};
}

}  // namespace vrlis::integration
