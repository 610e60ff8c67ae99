#pragma once
// The library's one table of samplers: every sampler is chosen at run time by name through
// these registries (core/registry.hpp). A new camera sampler is one header defining its
// entry and one line here.
#include <string>

#include "core/registry.hpp"
#include "samplers/auto_sampler.hpp"
#include "samplers/cauchy_mixture.hpp"
#include "samplers/cauchy_sum.hpp"
#include "samplers/equiangular.hpp"
#include "samplers/full_product.hpp"
#include "samplers/novak.hpp"
#include "samplers/vrl_marginal.hpp"
#include "samplers/vrl_point.hpp"

namespace vrlis {

// The vocabulary of "which sampler for which step":
// - a segment sampler picks a point on a segment seen from a point (built from a
//   SegmentQuery): step two of the medium-to-medium gather (on the camera segment), and the
//   one step of the surface gather (on the VRL) and of single scattering (on the camera segment);
// - a VRL sampler picks the point on the VRL in step one of the medium-to-medium gather
//   (built from a MediumGatherQuery);
// - GatherSamplers is the pair a renderer is configured with.
using SegmentSamplers =
    Registry<EquiangularEntry, NovakEntry, CauchySumEntry, CauchyMixtureEntry, FullProductEntry, AutoEntry>;
using VrlSamplers = Registry<VrlPointEntry, VrlMarginalEntry>;

using SegmentChoice = SegmentSamplers::Choice;
using VrlChoice = VrlSamplers::Choice;
inline constexpr auto kSegmentSamplers = SegmentSamplers::All();
inline constexpr auto kVrlSamplers = VrlSamplers::All();

template <typename Registry>
constexpr std::string_view Name(Choice<Registry> c) { return c.name(); }
inline std::optional<SegmentChoice> ParseSegmentSampler(std::string_view name) { return SegmentSamplers::Parse(name); }

// The samplers of a whole render: step one on the VRL, the segment sampler for every other
// step. Named "segment" (step one VrlPoint, as Novák et al.) or "segment+vrl", e.g. "novak",
// "full-product+marginal". Default-constructed, the one default of the library, the
// integration layer and vrl_render: `auto` with VrlPoint, meant with the effort control
// (effort/price.hpp), with which its efficiency lies below the best fixed sampler's in no
// measured scene (docs/renderer.md#effort).
struct GatherSamplers {
  SegmentChoice segment = SegmentSamplers::Of<AutoEntry>();
  VrlChoice vrl{};
  friend bool operator==(GatherSamplers a, GatherSamplers b) { return a.segment == b.segment && a.vrl == b.vrl; }
};

// A pair fixed at compile time: a gather call given one compiles that pair alone, where one
// given GatherSamplers compiles every registered pair (a build of a few seconds against most of
// a minute). It converts to the GatherSamplers it names.
template <typename CameraEntry, typename VrlEntry = VrlPointEntry>
struct FixedSamplers {
  using Camera = CameraEntry;
  using Vrl = VrlEntry;
  constexpr operator GatherSamplers() const { return {SegmentSamplers::Of<CameraEntry>(), VrlSamplers::Of<VrlEntry>()}; }
};

inline std::string Name(GatherSamplers m) {
  std::string name(m.segment.name());
  if (m.vrl != VrlSamplers::Of<VrlPointEntry>()) (name += "+") += m.vrl.name();
  return name;
}

inline std::optional<GatherSamplers> ParseGatherSamplers(std::string_view name) {
  std::size_t plus = name.find('+');
  std::optional<SegmentChoice> segment = ParseSegmentSampler(name.substr(0, plus));
  std::optional<VrlChoice> vrl =
      plus == std::string_view::npos ? VrlSamplers::Of<VrlPointEntry>() : VrlSamplers::Parse(name.substr(plus + 1));
  if (!segment || !vrl) return std::nullopt;
  return GatherSamplers{*segment, *vrl};
}

}  // namespace vrlis
