#pragma once
// The renderer's counted work (docs/maths.md#effort-work): what the effort control prices
// instead of the clock, in the library's work units (vrlis/effort/work.hpp). The library
// counts a gather call's own work in its tally; the scene counts its rays here. A pixel runs
// on one thread from start to end, so the work counted on that thread between two points of
// it is that pixel's, whatever the other threads do.
#include <cstdint>

#include "renderer_work.hpp"

namespace vrlis::integration {

// A visit of a VRL gather sample (EffortCall::visit_work): its occlusion ray and connection.
inline constexpr double kVisitWork = renderer_work::kOccluded + renderer_work::kConnect;

// The work counted on this thread so far.
inline double& ThreadWork() {
  thread_local double work = 0;
  return work;
}

// Path vertices counted on this thread so far: for tools/work_costs.sh, which fits
// renderer_work::kVertex by them.
inline std::uint64_t& ThreadVertices() {
  thread_local std::uint64_t vertices = 0;
  return vertices;
}

// One vertex of a camera, remainder or light path: its work beyond its rays (shading, phase
// and light sampling, transmittance), a constant.
inline void CountVertex() {
  ThreadWork() += renderer_work::kVertex;
  ++ThreadVertices();
}

// Adds the work counted on this thread during its scope to *work, if set. The scope counts
// from zero and hands its count on to the enclosing one at its end (unless `kept` is false:
// work that is not the enclosing scope's): a difference of two readings would round by what
// the thread did before, and images would depend on it.
class WorkScope {
 public:
  explicit WorkScope(double* work, bool kept = true) : work_(work), outer_(ThreadWork()), kept_(kept) {
    ThreadWork() = 0;
  }
  ~WorkScope() {
    const double inner = ThreadWork();
    if (work_) *work_ += inner;
    ThreadWork() = kept_ ? outer_ + inner : outer_;
  }
  WorkScope(const WorkScope&) = delete;
  WorkScope& operator=(const WorkScope&) = delete;

 private:
  double* work_;
  double outer_;
  bool kept_;
};

}  // namespace vrlis::integration
