#pragma once
// A sampler's row of the generated work tables (work_costs.hpp, one per path of the batched
// gathers' lanes; core/dispatch.hpp says which is in use) by name: what both the effort
// control (work.hpp) and auto's rule (samplers/auto_sampler.hpp) price a sample by.
#include <string_view>

#include "../core/dispatch.hpp"
#include "work_costs.hpp"

namespace vrlis {
namespace detail {
// The entry of lanes.samplers named `name`, or the costliest where none is (a sampler
// registered after the constants were measured is priced high rather than free).
constexpr work_costs::SamplerWork SamplerWorkOf(const work_costs::LaneWork& lanes, std::string_view name) {
  work_costs::SamplerWork costliest = lanes.samplers[0];
  for (const work_costs::SamplerWork& w : lanes.samplers) {
    if (w.name == name) return w;
    if (w.medium > costliest.medium) costliest = w;
  }
  return {name, costliest.medium, costliest.surface};
}
}  // namespace detail
}  // namespace vrlis
