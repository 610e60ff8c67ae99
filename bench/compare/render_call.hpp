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

namespace vrl_compare {

// A sampler here is a whole gather method: camera sampler and step one (docs/maths.md).
using Sampler = vrlis::GatherMethod;

inline std::string SamplerName(Sampler s) { return vrlis::Name(s); }
inline std::optional<Sampler> ParseSampler(const std::string& name) { return vrlis::ParseGatherMethod(name); }
// The default study: every camera sampler with Novák's step one.
inline std::vector<Sampler> AllSamplers() {
  std::vector<Sampler> all;
  for (vrlis::Method m : vrlis::kMethods) all.push_back({m, {}});
  return all;
}
inline const Sampler kBaseline = *vrlis::ParseGatherMethod("novak");  // every ratio is to Novák's sampler

// One VRL renderer of a scene; Render times a pass with the given camera sampler.
class PassRenderer {
 public:
  PassRenderer(const vrli::Scene& scene, const vrli::RenderSettings& settings) : scene_(scene), settings_(settings) {}
  vrli::Film Render(Sampler sampler, std::uint64_t seed, std::uint64_t pass, double* seconds) {
    vrli::RenderSettings settings = settings_;
    settings.transport.sampling = sampler;
    vrli::VrlRenderer renderer(scene_, settings);
    auto start = std::chrono::steady_clock::now();
    vrli::Film film = renderer.RenderPass(seed, pass, nullptr);
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return film;
  }

 private:
  const vrli::Scene& scene_;
  vrli::RenderSettings settings_;
};

inline vrli::Spectrum GatherWith(Sampler sampler, const vrli::Scene& scene, const vrli::CameraSegment& seg,
                                 const vrli::Vrl& vrl, vrli::Rng& rng) {
  return vrli::GatherMediumToMedium(sampler, scene, seg, vrl, rng);
}

}  // namespace vrl_compare
