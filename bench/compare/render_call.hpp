#pragma once
// The only place where vrl_compare names the renderer's sampler argument: every pass and
// every gather it makes goes through PassRenderer and GatherWith, and samplers are named and
// parsed here.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <vrlis/method.hpp>
#include <vrlis_integration/gather.hpp>
#include <vrlis_integration/renderer.hpp>

#include "sampler_roles.hpp"

namespace vrlis::compare {

// What the study compares: the gather's samplers, and whether the effort control
// (vrlis/effort/policy.hpp) decides how often each gather is taken. Named as the samplers,
// with "+effort" when the control is on.
struct Method {
  GatherSamplers sampler{};
  bool effort = false;
  bool operator==(const Method& o) const { return sampler == o.sampler && effort == o.effort; }
  bool operator!=(const Method& o) const { return !(*this == o); }
};

inline constexpr const char kEffortSuffix[] = "+effort";
inline std::string SamplerName(GatherSamplers s) { return vrlis::Name(s); }
inline std::string SamplerName(const Method& m) { return vrlis::Name(m.sampler) + (m.effort ? kEffortSuffix : ""); }
inline std::optional<Method> ParseSampler(std::string name) {
  const std::string suffix = kEffortSuffix;
  bool effort = name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  if (effort) name.resize(name.size() - suffix.size());
  auto s = vrlis::ParseGatherSamplers(name);
  if (!s) return std::nullopt;
  return Method{*s, effort};
}
// The default study: every camera sampler with Novák's step one (VrlPoint), and FullProduct
// with VrlMarginal as step one.
inline std::vector<Method> AllSamplers() {
  std::vector<Method> all;
  for (vrlis::SegmentChoice m : vrlis::kSegmentSamplers) all.push_back({{m, {}}, false});
  all.push_back({*vrlis::ParseGatherSamplers("full-product+marginal"), false});
  return all;
}
// A published method at fixed effort: a sampler from the literature (not ours, not a policy)
// with Novák's step one, every gather taken once.
inline bool IsFixedPublished(const Method& m) {
  return !m.effort && m.sampler.vrl == vrlis::VrlSamplers::Of<vrlis::VrlPointEntry>() &&
         vrlis::SegmentSamplers::WithEntry(m.sampler.segment, [](auto entry) {
           return !lab::kOwn<decltype(entry)> && !lab::kPolicy<decltype(entry)>;
         });
}
// Every ratio is to the lab's baseline (Novák's sampler) with Novák's step one, every gather
// taken once.
inline const Method kBaseline{vrlis::FixedSamplers<lab::Baseline>{}, false};

// One VRL renderer of a scene; Render times a pass with the given camera sampler.
class PassRenderer {
 public:
  PassRenderer(const vrlis::integration::Scene& scene, const vrlis::integration::RenderSettings& settings) : scene_(scene), settings_(settings) {}
  // With the effort control on or `auto` (whose image model it chooses either way), `price`
  // holds what the passes before this one taught it (one per replicate: a pass's decisions
  // see only earlier passes of its own render; a renderer that prices nothing ignores it), and
  // `marginal_scores` likewise which gathers VrlMarginal fits (without it every pass is a
  // first pass and fits every gather).
  vrlis::integration::Film Render(const Method& method, std::uint64_t seed, std::uint64_t pass, double* seconds,
                                  vrlis::EffortPrice* price = nullptr,
                                  vrlis::ScoreOctaves* marginal_scores = nullptr) {
    vrlis::integration::RenderSettings settings = settings_;
    settings.transport.sampling = method.sampler;
    settings.transport.effort.on = method.effort;
    vrlis::integration::VrlRenderer renderer(scene_, settings);
    if (price) renderer.set_effort_price(*price);
    if (marginal_scores) renderer.set_marginal_scores(*marginal_scores);
    auto start = std::chrono::steady_clock::now();
    vrlis::integration::Film film = renderer.RenderPass(seed, pass, nullptr);
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (price) *price = renderer.effort_price();
    if (marginal_scores) *marginal_scores = renderer.marginal_scores();
    return film;
  }

 private:
  const vrlis::integration::Scene& scene_;
  vrlis::integration::RenderSettings settings_;
};

inline vrlis::integration::Spectrum GatherWith(GatherSamplers sampler, const vrlis::integration::Scene& scene, const vrlis::integration::CameraSegment& seg,
                                 const vrlis::integration::Vrl& vrl, vrlis::integration::Rng& rng) {
  return vrlis::integration::GatherMediumToMedium(sampler, scene, seg, vrl, rng);
}

}  // namespace vrlis::compare
