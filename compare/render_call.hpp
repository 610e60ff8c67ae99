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

using Sampler = vrlis::Method;

inline std::string SamplerName(Sampler s) { return std::string(vrlis::Name(s)); }
inline std::optional<Sampler> ParseSampler(const std::string& name) { return vrlis::ParseMethod(name); }
inline std::vector<Sampler> AllSamplers() { return {vrlis::kMethods.begin(), vrlis::kMethods.end()}; }
inline constexpr Sampler kBaseline = vrlis::Method::Novak;  // every ratio is to Novák's sampler

// One VRL renderer of a scene; Render times a pass with the given camera sampler.
class PassRenderer {
 public:
  PassRenderer(const vrli::Scene& scene, const vrli::RenderSettings& settings) : renderer_(scene, settings) {}
  vrli::Film Render(Sampler sampler, std::uint64_t seed, std::uint64_t pass, double* seconds) {
    auto start = std::chrono::steady_clock::now();
    vrli::Film film = renderer_.RenderPass(sampler, seed, pass, nullptr);
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return film;
  }

 private:
  vrli::VrlRenderer renderer_;
};

inline vrli::Spectrum GatherWith(Sampler sampler, const vrli::Scene& scene, const vrli::CameraSegment& seg,
                                 const vrli::Vrl& vrl, vrli::Rng& rng) {
  return vrli::GatherMediumToMedium(sampler, scene, seg, vrl, rng);
}

}  // namespace vrl_compare
