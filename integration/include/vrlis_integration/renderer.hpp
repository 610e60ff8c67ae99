#pragma once
// Progressive renderers: each call renders one pass (one sample per pixel, and for the VRL
// renderer a fresh set of light paths) from (seed, pass) and, with the effort control on, what
// the renderer learned from the passes it rendered before; never from the thread count or a
// clock. A driver can interleave passes of several samplers, or renderers, in one process.
#include <atomic>
#include <cstdint>
#include <vector>

#include <vrlis/effort/marginal_fits.hpp>
#include <vrlis/effort/price.hpp>

#include "bound_choice.hpp"
#include "film.hpp"
#include "pixel_samples.hpp"
#include "scene.hpp"
#include "transport.hpp"
#include "work.hpp"

namespace vrlis::integration {

// The VRL bounds a render chooses among by default: the gathers whole and two bounds. Not 0,
// the path tracer: its pilot passes run without the effort control's price, which gains the
// gathers several times their pilot's efficiency (docs/renderer.md#bound-choice).
inline const std::vector<float> kAutoBounds = {kUnbounded, 1.f, 0.1f};

// A pass's VRLs and gathers, its seconds (wall clock: for the driver's report, never a
// decision) and its counted work, light and camera passes (work.hpp; the VRL renderer's).
struct PassStats {
  std::uint64_t vrls = 0, gathers = 0, vertices = 0;  // vertices: the camera pass's (work.hpp)
  double seconds = 0, work = 0;

  PassStats& operator+=(const PassStats& o) {
    vrls += o.vrls, gathers += o.gathers, vertices += o.vertices, seconds += o.seconds, work += o.work;
    return *this;
  }
};

struct RenderSettings {
  int width = 64, height = 64;
  int vrls_per_pass = 64;  // light paths per pass
  bool jitter = true;      // false: every sample through the pixel centre
  // With jitter: where in the pixel each pass samples. Stratified passes are not
  // independent, so a standard error from the pass-to-pass spread does not hold for them:
  // the tests and comparisons estimate from that spread and keep the default.
  PixelSamples pixel_samples = PixelSamples::Independent;
  TransportSettings transport;
  // If not empty, the VRL renderer chooses transport.vrl_bound among these per image by the
  // price of variance, 0 standing for no light paths at all (bound_choice.hpp); kAutoBounds
  // are vrl_render's default.
  std::vector<float> vrl_bounds;
  // If set, incremented after each finished image row (any thread), for progress displays.
  std::atomic<int>* rows_done = nullptr;
};

// A renderer of one scene with fixed settings, pass by pass.
class Renderer {
 public:
  Renderer(const Scene& scene, const RenderSettings& settings) : scene_(scene), settings_(settings) {}
  virtual ~Renderer() = default;
  // Pass number `pass` of the render seeded by `seed`.
  virtual Film RenderPass(std::uint64_t seed, std::uint64_t pass, PassStats* stats) = 0;

 protected:
  const Scene& scene_;
  RenderSettings settings_;
};

// The bidirectional VRL pipeline: light pass, then camera pass. With the transport's effort
// control on, or `auto` (whose image model the price chooses), the renderer learns the price
// of variance from each pass it renders and the next pass's gathers use it: a pass then
// depends on the passes this renderer rendered before it, each a function of (seed, pass),
// so a render still is of its seed alone (the price reads counted work, never a clock:
// work.hpp). With VrlMarginal as step one the same holds of which gathers it fits
// (TransportSettings::marginal_fraction), learned from the scores of the earlier passes.
class VrlRenderer : public Renderer {
 public:
  VrlRenderer(const Scene& scene, const RenderSettings& settings)
      : Renderer(scene, settings), price_(settings.width, settings.height, kVisitWork),
        bounds_(settings.vrl_bounds) {}
  Film RenderPass(std::uint64_t seed, std::uint64_t pass, PassStats* stats) override;
  const vrlis::EffortPrice& effort_price() const { return price_; }
  void set_effort_price(const vrlis::EffortPrice& price) { price_ = price; }
  // The scores VrlMarginal's fits are given by, learned like the price.
  const vrlis::ScoreOctaves& marginal_scores() const { return marginal_scores_; }
  void set_marginal_scores(const vrlis::ScoreOctaves& scores) { marginal_scores_ = scores; }
  // `auto` in both gathers: the image's model is the price's (EffortPrice::model), the
  // control on or off.
  bool ModelsPriced() const;
  // The choice of the VRL bound (RenderSettings::vrl_bounds), learned from the pilot passes.
  const BoundChoice& bound_choice() const { return bounds_; }

 private:
  // A pass, or the effort control's pilot (EffortPrice::InPilot's pixels, with `auto` its probe
  // first; its film not kept).
  Film RenderPixels(std::uint64_t seed, std::uint64_t pass, bool pilot, PassStats* stats);
  // Whether the price learns from the passes: the control on, or the image's model priced.
  bool Priced() const;

  vrlis::EffortPrice price_;
  BoundChoice bounds_;
  vrlis::ScoreOctaves marginal_scores_;  // of the passes rendered so far
};

// The reference: a volumetric path tracer with next-event estimation.
class PathTracingRenderer : public Renderer {
 public:
  using Renderer::Renderer;
  Film RenderPass(std::uint64_t seed, std::uint64_t pass, PassStats* stats) override;
};

}  // namespace vrlis::integration
