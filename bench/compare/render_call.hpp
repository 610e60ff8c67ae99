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

namespace vrlis::compare {

inline std::string SamplerName(GatherSamplers s) { return vrlis::Name(s); }
inline std::optional<GatherSamplers> ParseSampler(const std::string& name) { return vrlis::ParseGatherSamplers(name); }
// The default study: every camera sampler with Novák's step one.
inline std::vector<GatherSamplers> AllSamplers() {
  std::vector<GatherSamplers> all;
  for (vrlis::SegmentChoice m : vrlis::kSegmentSamplers) all.push_back({m, {}});
  return all;
}
// Every ratio is to the registry's baseline (Novák's sampler) with Novák's step one.
inline const GatherSamplers kBaseline{*vrlis::SegmentSamplers::Baseline(), vrlis::VrlSamplers::Of<vrlis::VrlPointEntry>()};

// One VRL renderer of a scene; Render times a pass with the given camera sampler.
class PassRenderer {
 public:
  PassRenderer(const vrlis::integration::Scene& scene, const vrlis::integration::RenderSettings& settings) : scene_(scene), settings_(settings) {}
  vrlis::integration::Film Render(GatherSamplers sampler, std::uint64_t seed, std::uint64_t pass, double* seconds) {
    vrlis::integration::RenderSettings settings = settings_;
    settings.transport.sampling = sampler;
    vrlis::integration::VrlRenderer renderer(scene_, settings);
    auto start = std::chrono::steady_clock::now();
    vrlis::integration::Film film = renderer.RenderPass(seed, pass, nullptr);
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
