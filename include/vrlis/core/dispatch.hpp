#pragma once
// The instruction set of the batched gathers, chosen at run time. The library's vector lanes
// are loops that the compiler vectorises for the build's target: 4 float lanes (SSE) in a
// default x86-64 build. Where the processor has AVX2, WithWidestLanes runs the same code
// compiled for it, 8 lanes (VrlMarginal's fit about twice as fast,
// docs/maths.md#vrl-marginal). Every sampler's gathers take the same path, so their
// comparison is that of the code, not of the flags. Not FMA: contracted multiply-adds round
// differently, and next to the camera line a weight moved by a percent between the paths;
// without them the paths agree to rounding (tests/gather/gather_batch.cpp), and the
// renderer's images came out bit for bit the same (FMA would add 10-15% more gathers per
// second). A build that already targets AVX2 (-march=x86-64-v3 and later), a compiler other
// than GCC or Clang, another architecture, or VRLIS_NO_DISPATCH defined before the first
// include runs the code as built, and so does every build after UseWidestLanes(false).
#if !defined(VRLIS_NO_DISPATCH) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(__AVX2__)
#define VRLIS_DISPATCH_AVX2 1
#else
#define VRLIS_DISPATCH_AVX2 0
#endif

#include <atomic>

namespace vrlis {
namespace detail {

// Whether the process lets WithWidestLanes take the AVX2 path (UseWidestLanes).
inline std::atomic<bool>& WidestLanesAllowed() {
  static std::atomic<bool> allowed{true};
  return allowed;
}

// Whether WithWidestLanes takes the AVX2 path on this processor (false without dispatch).
inline bool WidestLanesAvailable() {
#if VRLIS_DISPATCH_AVX2
  static const bool available = __builtin_cpu_supports("avx2");
  return available && WidestLanesAllowed().load(std::memory_order_relaxed);
#else
  return false;
#endif
}

// Whether the batched gathers run on AVX2 lanes, built for them or dispatched to them: the
// lanes whose counted work the effort control prices (effort/work.hpp).
inline bool Avx2LanesInUse() {
#if defined(__AVX2__)
  return true;
#else
  return WidestLanesAvailable();
#endif
}

#if VRLIS_DISPATCH_AVX2
// f() with everything it calls inlined and compiled for AVX2.
template <typename F>
[[gnu::flatten, gnu::target("avx2")]] void RunWithAvx2(F& f) {
  f();
}
#endif

// f() on the widest lanes available (see above); `widest` false: as built (for tests).
template <typename F>
void WithWidestLanes(F&& f, bool widest = true) {
#if VRLIS_DISPATCH_AVX2
  if (widest && WidestLanesAvailable()) return RunWithAvx2(f);
#endif
  static_cast<void>(widest);
  f();
}

}  // namespace detail

// use false: the batched gathers run as built from now on, not on the widest lanes the
// processor has; for benchmarks of that path (tools/work_costs.sh) and images to compare
// with a machine without AVX2 (the effort control's counted work follows the lanes, so its
// images differ between the paths). Call it before gathering, not while gathers run.
inline void UseWidestLanes(bool use) { detail::WidestLanesAllowed().store(use, std::memory_order_relaxed); }

}  // namespace vrlis
