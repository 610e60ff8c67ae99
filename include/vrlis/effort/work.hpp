#pragma once
// Counted work: what the effort control prices time by instead of a clock reading, so that a
// render is a function of its scene, settings and seed (docs/maths.md#effort-work). Each
// operation a gather call does costs a constant (work_costs.hpp, measured by
// tools/work_costs.sh); a unit is a nanosecond of the machine they were measured on, and only
// ratios of work enter a decision. A renderer counts the work of what it owns (its rays) in
// the same units.
#include <array>
#include <string_view>

#include "../method.hpp"
#include "work_costs.hpp"

namespace vrlis {
namespace detail {
// The entry of work_costs::kSamplers named `name`, or the costliest where none is (a sampler
// registered after the constants were measured is priced high rather than free).
constexpr work_costs::SamplerWork SamplerWorkOf(std::string_view name) {
  work_costs::SamplerWork costliest = work_costs::kSamplers[0];
  for (const work_costs::SamplerWork& w : work_costs::kSamplers) {
    if (w.name == name) return w;
    if (w.medium > costliest.medium) costliest = w;
  }
  return {name, costliest.medium, costliest.surface};
}
template <bool kSurface>
constexpr std::array<double, SegmentSamplers::kCount> SampleWorkTable() {
  std::array<double, SegmentSamplers::kCount> table{};
  for (std::size_t i = 0; i < SegmentSamplers::kCount; ++i) {
    const work_costs::SamplerWork w = SamplerWorkOf(SegmentSamplers::kNames[i]);
    table[i] = kSurface ? w.surface : w.medium;
  }
  return table;
}
// Built at compile time: a gather's batch looks its sampler up by index, not by name.
inline constexpr auto kMediumSampleWork = SampleWorkTable<false>();
inline constexpr auto kSurfaceSampleWork = SampleWorkTable<true>();
}  // namespace detail

// One sample of the batched medium-to-medium gather with this camera sampler after VrlPoint;
// VrlMarginal's fit, where a sample takes it, costs MarginalFitWork more.
constexpr double MediumSampleWork(SegmentChoice camera) {
  return detail::kMediumSampleWork[static_cast<std::size_t>(camera.index())];
}
constexpr double MarginalFitWork() { return work_costs::kMarginalFit; }
// One sample of the batched medium-to-surface gather with this sampler.
constexpr double SurfaceSampleWork(SegmentChoice sampler) {
  return detail::kSurfaceSampleWork[static_cast<std::size_t>(sampler.index())];
}

}  // namespace vrlis
