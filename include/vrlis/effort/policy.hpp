#pragma once
// How often to take one VRL gather (docs/maths.md#effort; Rath et al. 2022, "EARS:
// Efficiency-Aware Russian Roulette and Splitting"): q = sqrt(price x predicted second
// moment), clamped to [floor, ceiling], taken floor(q + u) times with weight 1 / q each:
// Russian roulette below one, splitting above, unbiased for any q > 0 (and q is never 0).
#include <algorithm>
#include <cmath>
#include <limits>

namespace vrlis {

// The model a gather is taken with (ChooseEffortModel): the sampler asked for (with `auto`, its
// per-query rule), the accurate one (VrlMarginal, FullProduct), the cheapest (VrlPoint,
// equiangular) or the thesis's mixture (VrlPoint, CauchyMixture).
enum class EffortModel { Chosen, Accurate, Cheapest, Mixture };
inline constexpr int kEffortModels = 4;

// The effort control's parameters. `price` is what one unit of a gather's second moment is
// worth in gathers: (image cost / image variance) / (cost of one gather), learned by the
// renderer from earlier passes only (a decision that saw the current pass would bias it).
// With `on` false, or no price learned yet (price not positive and finite), every gather is
// taken once with weight 1, as without the control (a deciding call still draws a number per
// VRL for it: the same image in distribution, not bit for bit; docs/porting.md#the-fast-path).
struct EffortSettings {
  bool on = false;
  double price = 0;
  // The largest roulette weight is 1 / floor. EARS clamps at 0.05; 0.01 halves a room pass
  // whose gathers carry no variance and changes no measured scene where they do
  // (docs/maths.md#effort).
  double floor = 0.01;
  double ceiling = 20;   // at most this many samples of one gather
  // The share of a gather's second moment that splitting reduces: its variance given the VRL
  // and the camera segment, over its second moment (the rest is the VRL's and the path's,
  // shared by every split sample); learned by the renderer like the price.
  double within = 1;
  // With the `auto` sampler, the accurate model (FullProduct, VrlMarginal as step one) for a
  // gather that asks for more than this many ceilings of samples (docs/maths.md#effort-models).
  double accurate = 2.3;
  // The whole call's demand, learned by the renderer from earlier calls like this one (e.g.
  // of the same pixel tile): sqrt((its second moment / the work its decisions take) x
  // (image cost / image variance)), docs/maths.md#effort-calls. Below one (and priced) the call is taken with that
  // probability, at least `floor` (one number drawn first), and each gather in a taken call
  // 1 / rate times as often: every gather's expected samples and weights stay those of its
  // own demand, and the calls not taken save their bounds. 1, more or NaN: every call taken.
  double call_demand = 1;
  // With the `auto` sampler: the model of this call's gathers below the accurate tier, auto's
  // per-query rule (Chosen), whose prediction and dispatch cost as much as an equiangular
  // gather and which knows the variance of one gather only, or one model for the whole image:
  // the cheapest, the mixture or the accurate one. The renderer's choice from earlier passes
  // (docs/maths.md#effort-cheapest); honoured with the control on, priced or not.
  EffortModel model = EffortModel::Chosen;
  // With the `auto` sampler: the rule's samples also carry their density over the mixture's
  // (GatherSample::over_mixture), at the cost of a mixture fit each, for the renderer to
  // weigh that model against the rule.
  bool measure_mixture = false;
  // Whether the call's gathers are decided one by one (bounds, roulette, splitting, the
  // accurate tier). False: each taken once with weight 1 and no bound computed, the model by
  // `model` alone; the renderer's choice from earlier passes where the decisions cost more
  // time than the variance they save is worth (docs/maths.md#effort-decide).
  bool decide = true;
  // With VrlMarginal as step one: the gathers whose predicted second moment
  // (MarginalFitScores) is below this take VrlPoint's density instead of the fit. One fit
  // costs about four Novák gathers, and a few gathers hold most of an image's variance; a
  // renderer sets it, pass by pass, to a quantile of the scores of the passes before
  // (ScoreOctaves; docs/maths.md#vrl-marginal-where). 0: every gather fitted; +infinity:
  // none. With the control on or off; not for `auto`'s accurate model, which the control
  // gives only to the gathers that ask for it.
  double marginal_threshold = 0;
};

// Whether the control has a price to decide by: on, deciding, and a positive finite price learned.
inline bool EffortPriced(const EffortSettings& e) {
  return e.on && e.decide && e.price > 0 && std::isfinite(e.price);
}

// How many samples a gather whose second moment is predicted as m2 asks for, before the
// clamps: sqrt(price x m2) (the first-order optimum, docs/maths.md#effort); 1 unpriced.
inline double EffortDemand(const EffortSettings& e, double m2) {
  if (!EffortPriced(e) || std::isnan(m2)) return 1;
  double q = std::sqrt(e.price * std::max(m2, 0.0));
  return std::isfinite(q) ? q : std::numeric_limits<double>::infinity();
}

// Splitting (q > 1) reduces only the within share of the second moment, so above one sample
// the demand is sqrt(within) as large (docs/maths.md#effort).
inline double SplitDemand(const EffortSettings& e, double demand) {
  return demand > 1 ? std::max(1.0, demand * std::sqrt(std::clamp(e.within, 0.0, 1.0))) : demand;
}

// The expected number of samples of a gather: its demand, split-scaled, clamped to [floor,
// ceiling]; of one whose second moment is predicted as m2. Never zero: a prediction that
// rounds to zero must not drop a gather that is not (a bias).
inline double EffortClamp(const EffortSettings& e, double demand) {
  return EffortPriced(e) ? std::clamp(SplitDemand(e, demand), e.floor, e.ceiling) : 1;
}
inline double EffortQ(const EffortSettings& e, double m2) { return EffortClamp(e, EffortDemand(e, m2)); }

// The probability that a call of gathers is taken (EffortSettings::call_demand).
inline double EffortCallRate(const EffortSettings& e) {
  return EffortPriced(e) && e.call_demand < 1 ? std::max(e.call_demand, e.floor) : 1;
}

// The model a gather's demand pays for (docs/maths.md#effort-models): far above the ceiling
// its variance outweighs its time, and the most accurate one wins; below, the per-query rule
// of the sampler asked for, at the floor too (the cheapest model's second moment can exceed
// the model-blind prediction many times), or the image's model where the call asks for one
// (EffortSettings::model).
inline EffortModel ChooseEffortModel(const EffortSettings& e, double demand) {
  if (EffortPriced(e) && SplitDemand(e, demand) >= e.accurate * e.ceiling) return EffortModel::Accurate;
  return e.on ? e.model : EffortModel::Chosen;
}

// floor(q + u) for u uniform in [0, 1): q samples on average, stochastically rounded.
inline int EffortSamples(double q, double u) { return static_cast<int>(std::floor(q + u)); }

}  // namespace vrlis
