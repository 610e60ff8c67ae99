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

// Step two: a point on a segment seen from a point (built from a SegmentQuery).
using CameraSamplers =
    Registry<EquiangularEntry, NovakEntry, CauchySumEntry, CauchyMixtureEntry, FullProductEntry, AutoEntry>;
// Step one of the medium-to-medium gather: a point on the VRL (built from a MediumGatherQuery).
using VrlSamplers = Registry<VrlPointEntry, VrlMarginalEntry>;

using Method = CameraSamplers::Choice;
using StepOne = VrlSamplers::Choice;
inline constexpr auto kMethods = CameraSamplers::All();
inline constexpr auto kStepOnes = VrlSamplers::All();

template <typename Registry>
constexpr std::string_view Name(Choice<Registry> c) { return c.name(); }
inline std::optional<Method> ParseMethod(std::string_view name) { return CameraSamplers::Parse(name); }

template <typename Real, typename F>
decltype(auto) WithSampler(Method m, const SegmentQuery<Real>& q, F&& f) {
  return CameraSamplers::With(m, q, std::forward<F>(f));
}

// A whole medium-to-medium gather: step one on the VRL, step two on the camera segment.
// Named "camera" (step one VrlPoint, as Novák et al.) or "camera+vrl", e.g. "novak",
// "full-product+marginal".
struct GatherMethod {
  Method camera{};
  StepOne vrl{};
  friend bool operator==(GatherMethod a, GatherMethod b) { return a.camera == b.camera && a.vrl == b.vrl; }
};

inline std::string Name(GatherMethod m) {
  std::string name(m.camera.name());
  if (m.vrl != VrlSamplers::Of<VrlPointEntry>()) (name += "+") += m.vrl.name();
  return name;
}

inline std::optional<GatherMethod> ParseGatherMethod(std::string_view name) {
  std::size_t plus = name.find('+');
  std::optional<Method> camera = ParseMethod(name.substr(0, plus));
  std::optional<StepOne> vrl =
      plus == std::string_view::npos ? VrlSamplers::Of<VrlPointEntry>() : VrlSamplers::Parse(name.substr(plus + 1));
  if (!camera || !vrl) return std::nullopt;
  return GatherMethod{*camera, *vrl};
}

}  // namespace vrlis
