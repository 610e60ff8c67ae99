#pragma once
// The image-level price of variance behind the effort control (docs/maths.md#effort), learned
// from the passes already rendered: the variance of one pass's pixel estimate, averaged over
// pixels with the largest thousandth left out (a few fireflies must not flip decisions; the
// predicted second moments keep theirs, and more left out here overprices variance), and the
// counted work a pixel and a gather cost (work.hpp); per pixel tile, what a whole call of
// gathers is worth. A
// pass's decisions read the price of the passes before it only: the renderer adds a pass
// after rendering it.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include <vrlis/effort/policy.hpp>

#include "film.hpp"

namespace vrlis::integration {

// What a pixel's gathers tell the price in a pass (every "work" counted, work.hpp): the
// gathers taken, the work of the calls that took them, the predicted second moments
// (vrlis::EffortTally) and the samples' own estimate of them. Of the gathers split into
// several samples: the sum of their within variances and of their second moments, each
// estimated from its own samples (the share splitting reduces). Of the calls
// (vrlis::EffortCallRate): how many, the sum of their rates and of rate x (contribution to the
// pixel)^2, an estimate of their second moments had each been taken
// (docs/maths.md#effort-calls). Of the work, that of sampling (the rest is the decisions'). Of
// the samples `auto` took by its rule, the sum of (effort weight x contribution)^2 x
// (GatherSample::over_equiangular - 1): an estimate of the variance the pixel would gain had
// they been taken with equiangular sampling; the same with over_mixture, of the rule's samples
// in calls that measured it (mixture_measured of them); and the samples and sampling work of
// the rule (its work from the calls that did not measure), the cheapest model and the mixture
// (docs/maths.md#effort-cheapest). Of the calls: how many decided their gathers
// (vrlis::EffortSettings::decide) and the VRLs all of them considered, taken or not. Of the
// decided gathers' samples (effort weight w, contribution y), the sums of w y^2 (w - 1) over
// the rouletted (w > 1) and the split (w < 1): estimates of the variance the decisions add and
// remove against every gather taken once (docs/maths.md#effort-decide). `measured` counts the
// decided calls' samples only, as `predicted` does. Of the calls paired with a statistics-only
// call of the same VRLs under the accurate model (GatherMediumToMedium's `pair`): that call's
// samples and their work, its work (not the pixel's), and how much it would have changed the
// pixel's value (docs/maths.md#effort-accurate); of a pixel, whether the renderer paired its
// calls (1) or not (0).
struct EffortStats {
  std::uint64_t gathers = 0;
  double work = 0, sample_work = 0, predicted = 0, measured = 0;
  double split_within = 0, split_second = 0;
  double calls = 0, call_rate = 0, call_m2 = 0;
  double decided = 0, vrls = 0, roulette_excess = 0, split_excess = 0;
  double cheapest_excess = 0, mixture_excess = 0, mixture_measured = 0;
  double rule_samples = 0, rule_work = 0, cheapest_samples = 0, cheapest_work = 0;
  double mixture_samples = 0, mixture_work = 0;
  double accurate_samples = 0, accurate_work = 0, pair_work = 0, pair_pixel = 0;
  Spectrum pair_delta;
  void operator+=(const EffortStats& o) {
    gathers += o.gathers, work += o.work, sample_work += o.sample_work;
    predicted += o.predicted, measured += o.measured;
    split_within += o.split_within, split_second += o.split_second;
    calls += o.calls, call_rate += o.call_rate, call_m2 += o.call_m2;
    decided += o.decided, vrls += o.vrls, roulette_excess += o.roulette_excess, split_excess += o.split_excess;
    cheapest_excess += o.cheapest_excess, mixture_excess += o.mixture_excess, mixture_measured += o.mixture_measured;
    rule_samples += o.rule_samples, rule_work += o.rule_work;
    cheapest_samples += o.cheapest_samples, cheapest_work += o.cheapest_work;
    mixture_samples += o.mixture_samples, mixture_work += o.mixture_work;
    accurate_samples += o.accurate_samples, accurate_work += o.accurate_work;
    pair_work += o.pair_work, pair_pixel += o.pair_pixel, pair_delta += o.pair_delta;
  }
};

// What a pixel's path-traced remainder tells the price in a pass (docs/maths.md#effort-remainder):
// the camera vertices it left, the paths it traced from them, their work, and the sum over
// the paths of (contribution to the pixel)^2 / rate, an unbiased estimate of the second moment
// of one path per vertex.
struct RemainderStats {
  double launches = 0, paths = 0, work = 0, m2 = 0;
  void operator+=(const RemainderStats& o) {
    launches += o.launches, paths += o.paths, work += o.work, m2 += o.m2;
  }
};

// The two gathers, each with its own calibration and cost: their bounds are not equally tight.
enum class GatherKind { Medium, Surface };

class EffortPrice {
 public:
  // The passes that take every gather once: the first price's variance comes from the one
  // pass's neighbouring pixels, the next from the passes over time.
  static constexpr int kMinPasses = 1;

  static constexpr int kTile = 8;  // pixels on a side of the tiles whose calls share a demand

  EffortPrice() = default;
  EffortPrice(int width, int height);

  // What each pixel's medium-to-medium and medium-to-surface gathers and its remainder tell
  // in the current pass, filled by the renderer. Kept with the price: allocated and zeroed
  // afresh, their pages were faulted in every pass (a fifth of a controlled cube pass).
  struct PixelStats {
    std::vector<EffortStats> medium, surface;
    std::vector<RemainderStats> remainder;
  };
  // The current pass's PixelStats, one per pixel, each to be overwritten by the pass (not
  // zeroed: at 48 x 48 that memset was a few percent of an equiangular pass).
  PixelStats& BeginPass();
  // One finished pass: its image, the work its pixels counted (summed over pixels) and
  // the PixelStats of BeginPass.
  void Add(const Film& pass, double pixel_work);
  // The decisions below are made once per pass, when Add refreshes the price: a pixel only
  // reads them.
  // The price of a gather: (pixel cost / pixel variance) / gather cost x (measured / predicted
  // second moments), in 1 / (predicted second moment); 0 before kMinPasses passes (every
  // gather taken once).
  double price(GatherKind kind) const { return price_[static_cast<int>(kind)]; }
  // The within share of the split gathers' second moments (vrlis::EffortSettings::within); 1
  // before any gather was split.
  double within(GatherKind kind) const {
    const EffortStats& g = gathers_[static_cast<int>(kind)];
    return g.split_second > 0 ? std::min(1.0, g.split_within / g.split_second) : 1;
  }
  // The demand of one call of the gathers at pixel (x, y) (vrlis::EffortSettings::call_demand):
  // sqrt((second moment / decision work of a taken call) x (pixel cost / pixel variance)),
  // both from the earlier calls of the pixel's tile (the work from the kind's calls while
  // the tile has taken few); 1 before kMinPasses passes.
  double call_demand(GatherKind kind, int x, int y) const {
    return call_demand_[static_cast<int>(kind)][Tile(x, y)];
  }
  // The paths the remainder asks for at a camera vertex of pixel (x, y), EARS's splitting
  // factor: sqrt((second moment / work of one path) x (pixel cost / pixel variance)) from
  // the earlier paths of the pixel's tile (the work of all paths while the tile has traced
  // few); 1 before a price is learned.
  double remainder_demand(int x, int y) const { return remainder_demand_[Tile(x, y)]; }
  // The model of `auto`'s gathers of this kind at a pixel in this pass
  // (vrlis::EffortSettings::model), u uniform in [0, 1) drawn for the pixel: of the rule, the
  // cheapest model, the mixture and the accurate model, the one whose variance over the
  // rule's (estimated over the image from the rule's own samples, the accurate model's from
  // the pairs) is worth the least against the work it saves or costs
  // (docs/maths.md#effort-cheapest); where that is not the rule, the rule with
  // probability kExplore, which keeps the estimates learning. Before any price, the cheapest
  // model and the mixture each with probability kPilot (their work is measured once).
  vrlis::EffortModel model(GatherKind kind, double u) const {
    if (passes_ < kMinPasses) return u < kPilot ? vrlis::EffortModel::Cheapest
                                     : u < 2 * kPilot ? vrlis::EffortModel::Mixture : vrlis::EffortModel::Chosen;
    return u < kExplore ? vrlis::EffortModel::Chosen : model_[static_cast<int>(kind)];
  }
  // Whether a pixel whose gathers of this kind take the rule also measures the mixture's
  // density at its samples (vrlis::EffortSettings::measure_mixture), u uniform in [0, 1):
  // always where the image takes another model (the rule's few exploring samples are then
  // the only estimate of either alternative), else with probability kMeasure (a mixture fit
  // per sample is not free).
  bool measure_mixture(GatherKind kind, double u) const {
    return u < kMeasure || model_[static_cast<int>(kind)] != vrlis::EffortModel::Chosen;
  }
  static constexpr double kExplore = 1.0 / 512, kPilot = 1.0 / 16, kMeasure = 1.0 / 32;
  // Whether a pixel of `auto` gathers its medium-to-medium VRLs a second time under the
  // accurate model, for the statistics alone (the renderer's pair; EffortStats::pair_delta), u
  // uniform in [0, 1) drawn for the pixel and its horizontal neighbour alike (x and x + 1, x
  // even): in the first kMinPasses passes, a kPairShare of the neighbours. The image had their
  // gathers taken the accurate model and the image rendered give the accurate model's variance
  // by the same estimator (docs/maths.md#effort-accurate). A share: in a pass of nothing but
  // gathers a pair costs several times the pixel, and a short render (8 passes of room in the
  // study) pays for the first pass's.
  bool pairs() const { return passes_ < kMinPasses; }  // whether this pass pairs any pixel
  bool pair(double u) const { return u < kPairShare; }   // whether a pixel of such a pass pairs
  static constexpr double kPairShare = 1.0 / 4;
  // A change of the image's model to or from the accurate one is made where its predicted
  // V x T is below kAccurateMargin of the other's: the rule's and the accurate model's
  // variances differ many-fold, and a render that changes between them often, or unlike
  // another render of the scene, is charged for the change.
  static constexpr double kAccurateMargin = 0.8;
  // Whether a pixel's gathers of this kind are decided one by one in this pass
  // (vrlis::EffortSettings::decide), u uniform in [0, 1) drawn for the pixel: where, over the
  // image's earlier decided calls, the decisions' work exceeds what the variance they save
  // is worth (docs/maths.md#effort-decide), with probability kExplore; elsewhere always.
  // Before any price, with probability kCalibrate: unpriced, a decided gather is taken once as
  // any other, and only its bounds, which calibrate the first price, cost (the tight one about
  // half a gather). Priced but before any pass has decided, with probability kTrial: where the
  // decisions do not pay, a pass that decided everywhere took twice an undecided one
  // (bidirectional scene, g = 0), and a share measures whether they pay as well.
  bool decide(GatherKind kind, double u) const {
    if (passes_ < kMinPasses) return u < kCalibrate;
    const int k = static_cast<int>(kind);
    if (!(passes_of_[1].decided[k] > 0)) return u < kTrial;
    return decisions_pay_[k] || u < kExplore;
  }
  static constexpr double kCalibrate = 1.0 / 8, kTrial = 1.0 / 4;
  int passes() const { return passes_; }
  // What the image's model was chosen from at the last refresh, per pixel and pass: the
  // variance and work of the rule (the measured mix of models less the others' shares),
  // and each alternative's change of both against it and its share of the measured samples;
  // `known` false where it could not be estimated. The variances come from the image and the
  // models' samples, the work counted.
  struct ModelChange {
    vrlis::EffortModel model = vrlis::EffortModel::Chosen;
    double dv = 0, dt = 0, share = 0;
    bool known = false;
  };
  struct ModelWeighing {
    double v_rule = 0, t_rule = 0;  // 0 where the measurements gave no estimate
    ModelChange cheapest{vrlis::EffortModel::Cheapest}, mixture{vrlis::EffortModel::Mixture},
        accurate{vrlis::EffortModel::Accurate};
  };
  const ModelWeighing& model_weighing(GatherKind kind) const { return weighing_[static_cast<int>(kind)]; }

 private:
  void Refresh();
  // What Refresh decides for the next pass: per kind, the image's model and whether the
  // decisions pay, per kind and tile the call demand, per tile the remainder's.
  ModelWeighing WeighModels(int kind) const;
  vrlis::EffortModel Model(int kind, const ModelWeighing& w) const;
  bool DecisionsPay(int kind) const;
  double CallDemand(int kind, std::size_t tile) const;
  double RemainderDemand(std::size_t tile) const;
  std::size_t Tile(int x, int y) const {
    return static_cast<std::size_t>(y / kTile) * static_cast<std::size_t>(tiles_x_) + static_cast<std::size_t>(x / kTile);
  }

  // Of the first kMinPasses passes, or of those after: per pixel, the sums of one pass's
  // RMS RGB value and of its square, and the pixels' work; per kind, the pixels that
  // called its gathers and those of them that decided the gathers under a price, and the
  // samples below the accurate tier and those of them the cheapest model and the mixture took.
  struct Passes {
    std::vector<double> sum, sum_sq;
    double pixel_work = 0;
    int count = 0;
    double called[2] = {0, 0}, decided[2] = {0, 0};
    double switchable[2] = {0, 0}, cheapest[2] = {0, 0}, mixture[2] = {0, 0};
  };
  int width_ = 0, height_ = 0, passes_ = 0;
  std::size_t pixels_ = 0;
  Passes passes_of_[2];
  // The variance and cost of a pixel per pass, of the estimator the decisions made.
  double variance_ = 0, pixel_cost_ = 0;
  double value_of_time() const { return variance_ > 0 ? pixel_cost_ / variance_ : 0; }
  // The passes those come from: the controlled ones once there are two (the first pass's
  // would stay in the sums long after).
  const Passes& measured() const { return passes_of_[1].count >= 2 ? passes_of_[1] : passes_of_[0]; }
  int tiles_x_ = 0;
  EffortStats gathers_[2];
  std::vector<EffortStats> tiles_[2];
  EffortStats uncontrolled_[2];  // of the first kMinPasses passes, which took every gather once
  EffortStats controlled_[2];    // of the passes after
  EffortStats decided_[2], undecided_[2];  // of those passes' pixels that decided their gathers, and the rest
  double price_[2] = {0, 0};
  vrlis::EffortModel model_[2] = {vrlis::EffortModel::Chosen, vrlis::EffortModel::Chosen};
  ModelWeighing weighing_[2];
  bool decisions_pay_[2] = {true, true};
  // The variance of a pixel per pass had the medium-to-medium gathers of the first pass taken
  // the accurate model, less that of the image rendered (both by neighbouring pixels'
  // differences); NaN before a pass paired them.
  double accurate_change_ = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> call_demand_[2], remainder_demand_;
  // This pass's stats summed per tile and kind, of the pixels that decided their gathers under a
  // price and of the rest (Add).
  std::vector<EffortStats> pass_tiles_[2][2];
  std::vector<RemainderStats> pass_remainder_;
  std::vector<RemainderStats> remainder_tiles_;
  RemainderStats remainder_;
  PixelStats pass_;
};

}  // namespace vrlis::integration
