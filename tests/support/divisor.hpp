#pragma once
// How much of the heaviest statistical tests runs. VRLIS_TEST_DIVISOR=D (the sanitize test
// preset's, CMakePresets.json: that run checks memory and undefined behaviour, not
// statistics) runs them on 1/D of their samples and configurations; unset, as in Release,
// they run in full. Their thresholds are computed from the counts they ran (chi-square
// p-values, z-scores with estimated standard errors), so they stay valid tests at 1/D.
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace vrlis::test {

inline long Divisor() {
  static const long d = [] {
    const char* text = std::getenv("VRLIS_TEST_DIVISOR");
    if (text == nullptr) return 1L;
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    // A typo must neither quietly run the whole suite under the sanitizers nor skip all of it.
    if (end == text || *end != '\0' || v < 1)
      throw std::invalid_argument("VRLIS_TEST_DIVISOR must be an integer >= 1, not '" + std::string(text) + "'");
    return v;
  }();
  return d;
}

// n divided, at least 1.
inline long Divided(long n) { return n / Divisor() > 1 ? n / Divisor() : 1; }

// Whether item i of a sequence runs: every Divisor()-th, the first included.
inline bool Kept(long i) { return i % Divisor() == 0; }

}  // namespace vrlis::test
