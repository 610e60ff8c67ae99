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
#include "lanes_work.hpp"

namespace vrlis {
// The counted work of one path of the batched gathers' lanes, its samplers' looked up by
// index (built at compile time: a gather's batch looks its sampler up by index, not by name).
struct CountedWork {
  work_costs::LaneWork operations;
  std::array<double, SegmentSamplers::kCount> medium_sample{}, surface_sample{};

  constexpr explicit CountedWork(const work_costs::LaneWork& lanes) : operations(lanes) {
    for (std::size_t i = 0; i < SegmentSamplers::kCount; ++i) {
      const work_costs::SamplerWork w = detail::SamplerWorkOf(lanes, SegmentSamplers::kNames[i]);
      medium_sample[i] = w.medium, surface_sample[i] = w.surface;
    }
  }
  // One sample of the batched medium-to-medium gather with this camera sampler after
  // VrlPoint; VrlMarginal's fit, where a sample takes it, costs operations.marginal_fit more.
  constexpr double MediumSample(SegmentChoice camera) const {
    return medium_sample[static_cast<std::size_t>(camera.index())];
  }
  // One sample of the batched medium-to-surface gather with this sampler.
  constexpr double SurfaceSample(SegmentChoice sampler) const {
    return surface_sample[static_cast<std::size_t>(sampler.index())];
  }
};

namespace detail {
inline constexpr CountedWork kAvx2Work{work_costs::kAvx2}, kBuiltWork{work_costs::kBuilt};
}  // namespace detail

// The counted work of the lanes this process's batched gathers take (core/dispatch.hpp): a
// render with the effort control is a function of its scene, settings, seed and that path.
inline const CountedWork& LanesWork() { return detail::Avx2LanesInUse() ? detail::kAvx2Work : detail::kBuiltWork; }

}  // namespace vrlis
