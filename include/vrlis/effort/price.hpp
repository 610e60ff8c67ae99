#pragma once
// The effort control's price learner (docs/maths.md#effort-price): a renderer hands each
// pixel the settings of Pixel(), feeds its gather calls' records, and after the pass its
// pixels' values and the work it counted outside the gathers (EndPass); the next pass's
// settings then come from the passes before it only, so an estimator stays unbiased and a
// render is a function of its seed (the work is counted, never clocked: work.hpp).
//
//   vrlis::EffortPrice price(width, height);
//   for (int pass = 0; pass < passes; ++pass) {
//     price.BeginPass(settings);                  // settings.on = true
//     for each pixel (x, y), its value[i]:
//       vrlis::PixelEffort effort = price.Pixel(x, y, uniform);
//       ... vrlis::GatherMediumVrls(..., visit, effort.Medium(weights));  // visit returns its contribution
//     price.EndPass(values);
//   }
//
// With base.decide false (BeginPass) the price chooses `auto`'s image model alone: no gather
// is decided and no split kind is asked for a count, so every gather is taken once with
// weight 1, as without the control (the fixed-effort `auto`; docs/maths.md#effort-cheapest).
//
// A renderer may first render a pilot (while PilotDue()): the pixels InPilot names, a quarter,
// on numbers of no pass, their values handed to EndPass (the others' not finite) and not kept
// in the image; the first pass then is already priced (docs/maths.md#effort-pilot). With
// `auto`, the pilot's probe (InProbe) first, its values handed to EndProbe. Pixel
// values are a scalar per pixel (our renderer: the RMS of its RGB), in the units the
// visitors' contributions and the weights are in. The variance of one pass's pixel estimate
// is averaged over pixels with the largest thousandth left out (a few fireflies must not flip
// decisions); per 8 x 8 tile of pixels, the price learns what a whole call and each split kind
// are worth.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "call.hpp"
#include "policy.hpp"
#include "record.hpp"
#include "work_costs.hpp"

namespace vrlis {

// The two gathers, each with its own calibration and cost: their bounds are not equally tight.
enum class GatherKind { Medium, Surface };

// One pixel's effort in a pass (EffortPrice::Pixel): the settings of its medium-to-medium and
// medium-to-surface calls, the statistics-only pair's (EffortPrice::Pairs), the samples per
// launch of the renderer's split sub-estimators (SplitKind), and the records its calls add to.
struct PixelEffort {
  EffortSettings medium, surface, pair;
  // Per SplitKind, the samples per launch the price asks for; NaN before it asks (unpriced, or
  // the control off): the renderer's own count (split_rate).
  double split_rates[kSplitKinds] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::quiet_NaN()};
  double visit_work = work_costs::kVisit;
  PixelRecord* record = nullptr;

  // Kind k's samples per launch: the price's, or `own` where it asks none.
  double split_rate(SplitKind k, double own) const {
    const double r = split_rates[static_cast<int>(k)];
    return std::isnan(r) ? own : r;
  }
  template <typename Real>
  EffortCall<Real> Medium(const Real* weights, ScoreOctaves* scores = nullptr) const {
    return {medium, weights, record ? &record->medium : nullptr, scores, visit_work};
  }
  template <typename Real>
  EffortCall<Real> Surface(const Real* weights) const {
    return {surface, weights, record ? &record->surface : nullptr, nullptr, visit_work};
  }
  // The medium-to-medium VRLs gathered again on the same numbers under the accurate model,
  // for the statistics alone: the visitor returns the contribution and adds nothing.
  template <typename Real>
  EffortCall<Real> Pair(const Real* weights) const {
    return {pair, weights, record ? &record->pair : nullptr, nullptr, visit_work};
  }
};

class EffortPrice {
 public:
  // The passes that take every gather once: the first price's variance comes from the one
  // pass's neighbouring pixels, the next from the passes over time.
  static constexpr int kMinPasses = 1;
  static constexpr int kTile = 8;  // pixels on a side of the tiles whose calls share a demand
  // The taken calls, or split samples, below which a tile's cost per call (per sample) is too
  // noisy, and the image's is taken instead.
  static constexpr double kFewInTile = 16;
  // The fewest samples per launch of each SplitKind once priced. The remainder is split where
  // it asks for more paths, never rouletted: its paths cost too little where it asks for fewer
  // (room: 0.3 ms of a 78 ms pass) to repay larger weights. VPL connections: two, so that every
  // gather measures their within variance; rouletted, corner's variance per pass rose 4.5-17
  // times (docs/maths.md#effort-split).
  static constexpr double kSplitFloor[kSplitKinds] = {1, 2, 2};
  // Shares of pixels: exploring the rule where the image takes another model, piloting the
  // cheapest model and the mixture before a price, measuring the mixture under the rule.
  static constexpr double kExplore = 1.0 / 512, kPilot = 1.0 / 16, kMeasure = 1.0 / 32;
  // Shares of pixels deciding before a price (their bounds calibrate it), and once priced
  // before any pass decided (a trial of whether decisions pay).
  static constexpr double kCalibrate = 1.0 / 8, kTrial = 1.0 / 4;
  // The share of horizontal pixel pairs that also gather under the accurate model in the first
  // pass (Pairs), and the margin a change to or from that model must pay (its variance and
  // the rule's differ many-fold, and a render that flips between them pays for the flip).
  static constexpr double kPairShare = 1.0 / 4, kAccurateMargin = 0.8;
  // The margin any other change of the image's model (to the accurate one: kAccurateMargin)
  // must pay against the model it has, the rule at first: a cheaper model's variance is
  // weighed from the rule's samples, which rarely draw the large weights it makes where it
  // misses a peaked lobe, so a small predicted gain can hide a loss of integer factors; and
  // a weighing that flips with its noise pays for the flips (docs/maths.md#effort-cheapest).
  static constexpr double kSwitchMargin = 0.9;

  EffortPrice() = default;
  // visit_work: the counted work of one of the renderer's visits (EffortCall::visit_work).
  EffortPrice(int width, int height, double visit_work = work_costs::kVisit)
      : width_(width),
        height_(height),
        pixels_(static_cast<std::size_t>(std::max(width, 0)) * static_cast<std::size_t>(std::max(height, 0))),
        tiles_x_((width + kTile - 1) / kTile),
        visit_work_(visit_work) {
    for (Passes& p : passes_of_) p.sum.resize(pixels_), p.sum_sq.resize(pixels_), p.taken.resize(pixels_);
    const std::size_t tiles = static_cast<std::size_t>(std::max(tiles_x_, 0)) *
                              static_cast<std::size_t>(std::max((height + kTile - 1) / kTile, 0));
    for (int kind = 0; kind < 2; ++kind) {
      tiles_[kind].resize(tiles);
      call_demand_[kind].assign(tiles, 1.0);
    }
    for (int k = 0; k < kSplitKinds; ++k) {
      split_tiles_[k].resize(tiles);
      split_demand_[k].assign(tiles, std::numeric_limits<double>::quiet_NaN());
    }
    records_.resize(pixels_);
  }

  // A new pass whose calls take `base` (its `on` true; the rest the renderer's, e.g.
  // marginal_threshold, and `decide` false for the image's model alone) with what the price
  // learned; every pixel's record emptied.
  void BeginPass(const EffortSettings& base) {
    base_ = base;
    std::fill(records_.begin(), records_.end(), PixelRecord{});
  }

  // Pixel (x, y)'s effort in this pass, from six numbers uniform in [0, 1) that uniform()
  // draws in order (the two gathers' model, their decisions, their measuring of the
  // mixture): the same numbers give the same settings. Each pixel on one thread at a time; a
  // pixel outside the image throws std::out_of_range.
  template <typename Uniform>
  PixelEffort Pixel(int x, int y, Uniform&& uniform) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_)
      throw std::out_of_range("vrlis::EffortPrice::Pixel: no such pixel");
    double u[6];
    for (double& v : u) v = double(uniform());
    PixelEffort p;
    p.visit_work = visit_work_;
    p.record = &records_[static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)];
    for (int k = 0; k < 2; ++k) {
      EffortSettings& e = k == 0 ? p.medium : p.surface;
      e = base_;
      e.price = price_[k], e.within = Within(k), e.call_demand = call_demand_[k][Tile(x, y)];
      e.model = Model(k, u[k]);
      e.decide = base_.decide && Decide(k, u[2 + k]);
      e.measure_mixture = e.model == EffortModel::Chosen && (u[4 + k] < FirstPass(kMeasure) || model_[k] != EffortModel::Chosen);
    }
    p.pair = p.medium;
    p.pair.decide = p.pair.measure_mixture = false;
    p.pair.model = EffortModel::Accurate;
    for (int k = 0; base_.decide && k < kSplitKinds; ++k)  // (NaN stays NaN: std::clamp would not keep it)
      if (const double demand = split_demand_[k][Tile(x, y)]; !std::isnan(demand))
        p.split_rates[k] = std::clamp(demand, kSplitFloor[k], std::max(kSplitFloor[k], base_.ceiling));
    return p;
  }

  // Whether the next pass is the pilot, and whether pixel (x, y) takes part in it: horizontal
  // pairs (x even and x + 1, for the neighbour variance), one pair in four along each row,
  // staggered from row to row, so that each 8 x 8 tile holds 16 (docs/maths.md#effort-pilot).
  // The shares of pixels above are of the image's; the first pass takes each over kPilotShare,
  // the share of the pixels a pilot renders, so that as many pixels take it.
  static constexpr double kPilotShare = 1.0 / 4;
  bool PilotDue() const { return passes_ == 0; }
  static bool InPilot(int x, int y) { return (x / 2 + y) % 4 == 0; }

  // The pilot's probe: its pixels in one row of eight (two in each 8 x 8 tile), which a
  // renderer may render first and hand to EndProbe, so that the rest of the pilot pairs its
  // pixels only where pairs can pay (docs/maths.md#effort-probe).
  static bool InProbe(int x, int y) { return InPilot(x, y) && y % 8 == 0; }

  // Whether pixel (x, y) of `auto` also gathers its medium-to-medium VRLs under the accurate
  // model, for the statistics alone (PixelEffort::Pair), u uniform in [0, 1) and the same for
  // horizontal neighbours (x and x + 1, x even): in the pilot, outside its probe, a kPairShare
  // of them, unless the probe showed that pairs cannot pay. The image rendered and the image
  // had those gathers taken the accurate model give both models' variances by one estimator
  // (docs/maths.md#effort-accurate).
  bool Pairs(int x, int y, double u) const {
    return passes_ < kMinPasses && pairs_pay_ && !InProbe(x, y) && u < FirstPass(kPairShare);
  }

  // The probe's pixel values (row-major, width x height; not finite: not rendered), after its
  // pixels and before the rest of the pilot. The accurate model can remove at most the variance
  // of the medium-to-medium gathers given the pixel's path and the pass's VRLs: the sum of
  // their samples' variances (each VRL's sample has numbers of its own), at most the sum of
  // their squares. Where that is below 1 - kAccurateMargin of the pixel variance even a free
  // accurate model would not be taken, and the pilot pairs none.
  void EndProbe(const std::vector<double>& values) {
    if (values.size() != pixels_) throw std::invalid_argument("vrlis::EffortPrice::EndProbe: one value per pixel");
    double sum_sq = 0, rendered = 0;
    for (std::size_t i = 0; i < pixels_; ++i)
      if (std::isfinite(values[i])) sum_sq += records_[i].medium.sum_sq, ++rendered;
    const double variance = NeighbourVariance(values);
    probe_ = {rendered > 0 ? sum_sq / rendered : 0, variance};
    pairs_pay_ = !(variance > 0) || probe_.medium_sum_sq >= (1 - kAccurateMargin) * variance;  // no estimate: pair
  }
  // What the probe measured (zeros before it): per pixel, the medium-to-medium samples' sum of
  // squares and the variance; whether the pilot pairs.
  struct Probe {
    double medium_sum_sq = 0, variance = 0;
  };
  const Probe& probe() const { return probe_; }
  bool pairs_pay() const { return pairs_pay_; }

  // One finished pass: each pixel's value (row-major, width x height; another count throws
  // std::invalid_argument; not finite: not rendered) and the work the renderer counted outside
  // its gather calls (the records count theirs).
  void EndPass(const std::vector<double>& values, double other_work = 0) {
    if (values.size() != pixels_) throw std::invalid_argument("vrlis::EffortPrice::EndPass: one value per pixel");
    Passes& into = passes_of_[passes_ >= kMinPasses];
    std::vector<EffortRecord> pass_tiles[2][2];  // per kind, undecided or decided, per tile
    for (auto& kind : pass_tiles)
      for (auto& part : kind) part.resize(split_tiles_[0].size());
    std::vector<SplitRecord> pass_split[kSplitKinds];
    for (auto& kind : pass_split) kind.resize(split_tiles_[0].size());
    double work = other_work, pairs = 0;
    for (std::size_t i = 0; i < pixels_; ++i) {
      const PixelRecord& r = records_[i];
      const std::size_t tile = Tile(static_cast<int>(i % static_cast<std::size_t>(width_)),
                                    static_cast<int>(i / static_cast<std::size_t>(width_)));
      for (int k = 0; k < kSplitKinds; ++k) pass_split[k][tile] += r.split[k];
      work += r.medium.work + r.surface.work;
      pairs += r.pair.calls;
      for (int m = 0; m < kEffortModels; ++m) pair_samples_[m] += r.pair.model_samples[m], pair_work_[m] += r.pair.model_work[m];
      for (int kind = 0; kind < 2; ++kind) {
        const EffortRecord& p = kind == 0 ? r.medium : r.surface;
        if (!(p.calls > 0)) continue;
        const bool decided = price_[kind] > 0 && p.decided > 0;  // the first pass takes every gather once
        pass_tiles[kind][decided][tile] += p;
        ++into.called[kind];
        if (decided) ++into.decided[kind];
      }
    }
    EffortRecord total[2];
    for (std::size_t tile = 0; tile < split_tiles_[0].size(); ++tile) {
      for (int k = 0; k < kSplitKinds; ++k) split_[k] += pass_split[k][tile], split_tiles_[k][tile] += pass_split[k][tile];
      for (int kind = 0; kind < 2; ++kind)
        for (int decided = 0; decided < 2; ++decided) {
          const EffortRecord& p = pass_tiles[kind][decided][tile];
          total[kind] += p;
          tiles_[kind][tile] += p;
          if (price_[kind] > 0) (decided ? decided_ : undecided_)[kind] += p;
        }
    }
    for (int kind = 0; kind < 2; ++kind) {
      const EffortRecord& t = total[kind];
      const double* m = t.model_samples;
      into.switchable[kind] += m[int(EffortModel::Chosen)] + m[int(EffortModel::Cheapest)] + m[int(EffortModel::Mixture)];
      into.cheapest[kind] += m[int(EffortModel::Cheapest)], into.mixture[kind] += m[int(EffortModel::Mixture)];
    }
    for (std::size_t i = 0; i < pixels_; ++i) {
      const double v = values[i];
      if (!std::isfinite(v)) continue;
      into.sum[i] += v, into.sum_sq[i] += v * v;
      ++into.taken[i], ++into.rendered;
    }
    if (pairs > 0 && width_ >= 2) MeasureAccurate(values);
    into.work += work;
    last_pass_work_ = work;
    ++into.count;
    for (int kind = 0; kind < 2; ++kind) {
      gathers_[kind] += total[kind];
      (price_[kind] > 0 ? controlled_ : uncontrolled_)[kind] += total[kind];
    }
    ++passes_;
    if (passes_ >= kMinPasses) Refresh();
  }

  // What the price learned: the price of a gather (EffortSettings::price), 0 before
  // kMinPasses passes; the within share of split gathers' second moments (EffortSettings::
  // within); a call's demand at pixel (x, y) (EffortSettings::call_demand); a split kind's
  // samples per launch there before the clamps (NaN before a price); the image's model;
  // whether decisions pay.
  double price(GatherKind kind) const { return price_[static_cast<int>(kind)]; }
  double within(GatherKind kind) const { return Within(static_cast<int>(kind)); }
  double call_demand(GatherKind kind, int x, int y) const { return call_demand_[static_cast<int>(kind)][Tile(x, y)]; }
  double split_demand(SplitKind k, int x, int y) const { return split_demand_[static_cast<int>(k)][Tile(x, y)]; }
  EffortModel model(GatherKind kind) const { return model_[static_cast<int>(kind)]; }
  bool decisions_pay(GatherKind kind) const { return decisions_pay_[static_cast<int>(kind)]; }
  int passes() const { return passes_; }
  // The work the last pass counted, its gathers' and the renderer's own.
  double pass_work() const { return last_pass_work_; }
  // The records of the current pass's pixels (row-major), for a renderer's reports.
  const std::vector<PixelRecord>& records() const { return records_; }

  // What the image's model was chosen from at the last refresh, per pixel and pass: the
  // variance and work of the rule (the measured mix of models less the others' shares), and
  // each alternative's change of both against it and its share of the measured samples;
  // `known` false where it could not be estimated (docs/maths.md#effort-models).
  struct ModelChange {
    EffortModel model = EffortModel::Chosen;
    double dv = 0, dt = 0, share = 0;
    bool known = false;
  };
  struct ModelWeighing {
    double v_rule = 0, t_rule = 0;  // 0 where the measurements gave no estimate
    ModelChange cheapest{EffortModel::Cheapest}, mixture{EffortModel::Mixture}, accurate{EffortModel::Accurate};
  };
  const ModelWeighing& model_weighing(GatherKind kind) const { return weighing_[static_cast<int>(kind)]; }
  // The same at the first refresh, the only one that weighs the accurate model.
  const ModelWeighing& first_weighing(GatherKind kind) const { return first_weighing_[static_cast<int>(kind)]; }

 private:
  // Of the first kMinPasses passes, or of those after: per pixel, the sums of a pass's value
  // and its square and the passes that rendered it; the pixels rendered over all passes, and
  // the passes' work; per kind, the pixels that called its gathers and
  // those that decided them under a price, and the samples below the accurate tier and those
  // of them the cheapest model and the mixture took.
  struct Passes {
    std::vector<double> sum, sum_sq;
    std::vector<int> taken;
    double rendered = 0, work = 0;
    int count = 0;
    double called[2] = {0, 0}, decided[2] = {0, 0};
    double switchable[2] = {0, 0}, cheapest[2] = {0, 0}, mixture[2] = {0, 0};
  };

  std::size_t Tile(int x, int y) const {
    return static_cast<std::size_t>(y / kTile) * static_cast<std::size_t>(tiles_x_) + static_cast<std::size_t>(x / kTile);
  }
  double FirstPass(double share) const { return passes_ < kMinPasses ? share / kPilotShare : share; }
  double Within(int k) const {
    const EffortRecord& g = gathers_[k];
    return g.split_second > 0 ? std::min(1.0, g.split_within / g.split_second) : 1;  // 1 before any split
  }
  // The model of `auto`'s gathers for a pixel, u uniform in [0, 1): the image's, and the rule
  // with probability kExplore where that is another; before any price the cheapest model and
  // the mixture each with probability kPilot (their work is measured once).
  EffortModel Model(int k, double u) const {
    const double pilot = FirstPass(kPilot);
    if (passes_ < kMinPasses) return u < pilot ? EffortModel::Cheapest : u < 2 * pilot ? EffortModel::Mixture : EffortModel::Chosen;
    return u < kExplore ? EffortModel::Chosen : model_[k];
  }
  // Whether a pixel's gathers are decided one by one: before a price with probability
  // kCalibrate (unpriced, a decided gather is taken once and only its bounds cost); priced
  // but before any pass decided, kTrial; then where decisions pay, else kExplore.
  bool Decide(int k, double u) const {
    if (passes_ < kMinPasses) return u < FirstPass(kCalibrate);
    if (!(passes_of_[1].decided[k] > 0)) return u < kTrial;
    return decisions_pay_[k] || u < kExplore;
  }
  const Passes& measured() const { return passes_of_[1].count >= 2 ? passes_of_[1] : passes_of_[0]; }
  double value_of_time() const { return variance_ > 0 ? pixel_cost_ / variance_ : 0; }

  static double TrimmedMean(std::vector<double> values) {
    if (values.empty()) return 0;
    const std::size_t kept = values.size() - values.size() / 1000;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(kept) - 1, values.end());
    double sum = 0;
    for (std::size_t k = 0; k < kept; ++k) sum += values[k];
    return sum / double(kept);
  }
  // Half the squared difference of horizontal neighbours (x and x + 1, x even; edges overstate
  // it), trimmed; of the pairs whose first pixel `use` flags, if given, and both rendered.
  double NeighbourVariance(const std::vector<double>& values, const std::vector<bool>* use = nullptr) const {
    std::vector<double> pairs;
    for (int y = 0; y < height_; ++y)
      for (int x = 0; x + 1 < width_; x += 2) {
        const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
        if (use && !(*use)[i]) continue;
        const double d = values[i] - values[i + 1];
        if (!std::isfinite(d)) continue;
        pairs.push_back(d * d / 2);
      }
    return TrimmedMean(std::move(pairs));
  }
  // The paired pixels' accurate image against the whole rendered one: over the paired pixels
  // alone the rendered image's rare large samples, which the accurate image lacks, would
  // make the difference's noise.
  void MeasureAccurate(const std::vector<double>& values) {
    std::vector<double> accurate(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(pixels_));
    std::vector<bool> paired(pixels_);
    for (std::size_t i = 0; i < pixels_; ++i) {
      const PixelRecord& r = records_[i];
      accurate[i] += r.pair.sum - r.medium.sum;
      paired[i] = r.pair.calls > 0 && (i % static_cast<std::size_t>(width_)) + 1 < static_cast<std::size_t>(width_) &&
                  records_[i + 1].pair.calls > 0;
    }
    const double change = NeighbourVariance(accurate, &paired) - NeighbourVariance(values);
    if (std::isfinite(change)) accurate_change_ = change;
  }

  void Refresh() {
    const Passes& p = measured();
    const double n = p.count;
    double variance = 0;
    if (n >= 2) {
      std::vector<double> pixels;
      for (std::size_t i = 0; i < pixels_; ++i) {  // each pixel's variance over the passes that rendered it
        const double k = p.taken[i], mean = k > 0 ? p.sum[i] / k : 0;
        if (k >= 2) pixels.push_back(std::max(0.0, (p.sum_sq[i] - k * mean * mean) / (k - 1)));
      }
      variance = TrimmedMean(std::move(pixels));
    } else {
      if (width_ < 2) return;
      std::vector<double> once(p.sum);  // (the pixels not rendered are not neighbours)
      for (std::size_t i = 0; i < pixels_; ++i)
        if (p.taken[i] == 0) once[i] = std::numeric_limits<double>::quiet_NaN();
      variance = NeighbourVariance(once);
    }
    if (!(p.rendered > 0)) return;
    variance_ = variance, pixel_cost_ = p.work / p.rendered;
    for (int kind = 0; kind < 2; ++kind) {
      const EffortRecord& g = gathers_[kind];
      const EffortRecord& u = uncontrolled_[kind];
      const EffortRecord& c = controlled_[kind];
      // One gather's cost, its decision's included, from the passes that took every gather once
      // (the controlled passes charge the decisions of the gathers not taken to those taken, a
      // feedback), scaled to the models the controlled passes chose by their sampling work.
      auto sampling = [](const EffortRecord& s) { return s.samples > 0 ? s.sample_work / s.samples : 0.0; };
      const double models = sampling(c) > 0 && sampling(u) > 0 ? sampling(c) / sampling(u) : 1;
      const double gather_cost = u.samples > 0 ? models * u.work / u.samples : 0;
      const double calibration = g.predicted > 0 ? g.measured / g.predicted : 0;
      price_[kind] = variance > 0 && gather_cost > 0 && calibration > 0 ? calibration * pixel_cost_ / (variance * gather_cost) : 0;
    }
    for (int kind = 0; kind < 2; ++kind) {
      weighing_[kind] = WeighModels(kind);
      if (passes_ == kMinPasses) first_weighing_[kind] = weighing_[kind];
      model_[kind] = ChooseModel(kind, weighing_[kind]);
      decisions_pay_[kind] = DecisionsPay(kind);
      for (std::size_t tile = 0; tile < call_demand_[kind].size(); ++tile) call_demand_[kind][tile] = CallDemand(kind, tile);
    }
    for (int k = 0; k < kSplitKinds; ++k)
      for (std::size_t tile = 0; tile < split_demand_[k].size(); ++tile) split_demand_[k][tile] = SplitFactor(k, tile);
  }

  // EARS's splitting factor of a split kind's samples per launch in a tile:
  // sqrt((m2 / work of one sample) x (pixel cost / pixel variance)), the work of all the
  // kind's samples while the tile has taken few (docs/maths.md#effort-split); NaN unknown.
  double SplitFactor(int k, std::size_t t) const {
    const SplitRecord& tile = split_tiles_[k][t];
    const SplitRecord& counted = tile.samples >= kFewInTile ? tile : split_[k];
    const double cost = counted.samples > 0 ? counted.work / counted.samples : 0;
    if (!(value_of_time() > 0) || !(cost > 0) || !(tile.launches > 0)) return std::numeric_limits<double>::quiet_NaN();
    return std::sqrt(tile.m2 / tile.launches / cost * value_of_time());
  }

  // A call's demand in a tile: sqrt((second moment / decision work of a taken call) x (pixel
  // cost / pixel variance)), the kind's work while the tile has taken few (docs/maths.md#effort-calls).
  double CallDemand(int kind, std::size_t t) const {
    const EffortRecord& tile = tiles_[kind][t];
    const EffortRecord& all = gathers_[kind];
    auto decisions = [](const EffortRecord& s) { return (s.work - s.sample_work) / s.call_rate; };
    const double cost = tile.call_rate >= kFewInTile ? decisions(tile) : all.call_rate > 0 ? decisions(all) : 0;
    if (!(value_of_time() > 0) || !(cost > 0) || !(tile.calls > 0)) return 1;
    return std::sqrt(tile.call_m2 / tile.calls / cost * value_of_time());
  }

  ModelWeighing WeighModels(int k) const {
    ModelWeighing w;
    const EffortRecord& all = gathers_[k];
    // The models' work per sample from the first passes only, where each took every gather
    // once in whole batches: a controlled pass takes the image's model in the small batches
    // roulette leaves, at a higher cost per sample that the others, not taken, never show.
    const EffortRecord& pilot = uncontrolled_[k];
    const Passes& p = measured();
    const double switchable = p.switchable[k];
    constexpr int kRule = int(EffortModel::Chosen), kCheapest = int(EffortModel::Cheapest);
    constexpr int kMixture = int(EffortModel::Mixture), kAccurate = int(EffortModel::Accurate);
    const double all_rule = all.model_samples[kRule] - all.mixture_measured;
    const double pilot_rule = pilot.model_samples[kRule] - pilot.mixture_measured;
    if (!(all_rule > 0 && pilot_rule > 0 && switchable > 0 && variance_ > 0 && pixel_cost_ > 0)) return w;
    // Per pixel and pass, what a model changes against the rule were every sample below the
    // accurate tier taken with it: the variance it adds (estimated from the rule's samples) and
    // its work over the rule's; and its share of those samples in the measured passes.
    const double samples = switchable / p.rendered;
    const double rule_work = pilot.model_work[kRule] / pilot_rule;
    auto change = [&](ModelChange& c, double excess, double measured, int model, double share) {
      const double taken = pilot.model_samples[model];
      if (!(measured > 0 && taken > 0)) return;
      c.dv = samples * excess / measured, c.dt = samples * (pilot.model_work[model] / taken - rule_work);
      c.share = share, c.known = true;
    };
    change(w.cheapest, all.cheapest_excess, all.model_samples[kRule], kCheapest, p.cheapest[k] / switchable);
    change(w.mixture, all.mixture_excess, all.mixture_measured, kMixture, p.mixture[k] / switchable);
    // The accurate model's variance from the pairs' image (medium gathers, first priced refresh
    // only), its work from the pairs' own. The pairs' image is against the first pass's, whose
    // pilots took the cheapest model and the mixture: its change against the rule adds theirs.
    if (k == int(GatherKind::Medium) && passes_ == kMinPasses && !std::isnan(accurate_change_) &&
        pair_samples_[kAccurate] > 0)
      w.accurate = {EffortModel::Accurate,
                    accurate_change_ + w.cheapest.share * w.cheapest.dv + w.mixture.share * w.mixture.dv,
                    samples * (pair_work_[kAccurate] / pair_samples_[kAccurate] - rule_work), 0, true};
    // The measured variance and cost are of a mix, each model's share of the samples with its
    // change and the rest with the rule's: the states compared whole, not to first order.
    w.v_rule = variance_, w.t_rule = pixel_cost_;
    for (const ModelChange* c : {&w.cheapest, &w.mixture, &w.accurate}) w.v_rule -= c->share * c->dv, w.t_rule -= c->share * c->dt;
    return w;
  }

  // The model with the least V x T, any change from the image's present model by a margin;
  // the accurate one weighed once, at the first price, and kept (a render that flips between
  // it and the rule pays for the flip).
  EffortModel ChooseModel(int k, const ModelWeighing& w) const {
    if (model_[k] == EffortModel::Accurate) return EffortModel::Accurate;
    if (!(w.v_rule > 0 && w.t_rule > 0)) return EffortModel::Chosen;  // none, or estimates that contradict the measurement
    const ModelChange rule{EffortModel::Chosen, 0, 0, 0, true};
    auto product = [&](const ModelChange& c) {
      const double v = w.v_rule + c.dv;
      return c.known && v > 0 ? v * (w.t_rule + c.dt) : std::numeric_limits<double>::infinity();
    };
    const ModelChange* present = &rule;
    for (const ModelChange* c : {&w.cheapest, &w.mixture})
      if (c->model == model_[k] && std::isfinite(product(*c))) present = c;
    EffortModel best = present->model;
    double least = product(*present);
    for (const ModelChange* c : {&rule, &w.cheapest, &w.mixture, &w.accurate}) {
      if (c == present) continue;
      const double score = product(*c) / (c->model == EffortModel::Accurate ? kAccurateMargin : kSwitchMargin);
      if (score < least) least = score, best = c->model;
    }
    return best;
  }

  // Whether deciding gathers one by one pays: the variance the decisions add (negative:
  // remove) and their work against each gather taken once, both states compared whole
  // (docs/maths.md#effort-decide).
  bool DecisionsPay(int k) const {
    const EffortRecord& d = decided_[k];
    const EffortRecord& once = undecided_[k];
    const double decided_pixels = passes_of_[1].decided[k];
    if (!(decided_pixels > 0 && variance_ > 0 && pixel_cost_ > 0)) return true;
    const EffortRecord& counted = d.samples > 0 ? d : uncontrolled_[k];
    const double sample_cost = counted.samples > 0 ? counted.sample_work / counted.samples : 0;
    const double loop = once.vrls > 0 ? (once.work - once.sample_work) / once.vrls : 0;
    const double work = (d.work - d.sample_work) - d.vrls * loop + (d.samples - d.vrls) * sample_cost;
    const Passes& p = measured();
    const double scale = p.called[k] / p.rendered / decided_pixels;
    const double dv = scale * (d.roulette_excess + Within(k) * d.split_excess), dt = scale * work;
    const double decided_share = p.called[k] > 0 ? p.decided[k] / p.called[k] : 0;
    const double v_once = variance_ - decided_share * dv, t_once = pixel_cost_ - decided_share * dt;
    if (!(v_once > 0)) return true;   // the variance they add estimated above the whole: keep them
    if (!(t_once > 0)) return false;  // the time they take estimated above the whole
    return (v_once + dv) * (t_once + dt) < v_once * t_once;
  }

  int width_ = 0, height_ = 0, passes_ = 0;
  std::size_t pixels_ = 0;
  int tiles_x_ = 0;
  double visit_work_ = work_costs::kVisit;
  EffortSettings base_;
  std::vector<PixelRecord> records_;  // the current pass's, per pixel
  Passes passes_of_[2];
  double variance_ = 0, pixel_cost_ = 0, last_pass_work_ = 0;
  EffortRecord gathers_[2];
  std::vector<EffortRecord> tiles_[2];
  EffortRecord uncontrolled_[2];  // of the first kMinPasses passes, which took every gather once
  EffortRecord controlled_[2];    // of the passes after
  EffortRecord decided_[2], undecided_[2];  // of those passes' pixels that decided their gathers, and the rest
  double pair_samples_[kEffortModels] = {}, pair_work_[kEffortModels] = {};  // the pairs' samples and work, by model
  double price_[2] = {0, 0};
  EffortModel model_[2] = {EffortModel::Chosen, EffortModel::Chosen};
  ModelWeighing weighing_[2], first_weighing_[2];
  bool decisions_pay_[2] = {true, true};
  // The variance of a pixel per pass had the medium-to-medium gathers of the first pass taken
  // the accurate model, less that of the image rendered; NaN before a pass paired them.
  double accurate_change_ = std::numeric_limits<double>::quiet_NaN();
  Probe probe_;
  bool pairs_pay_ = true;  // until a probe shows otherwise
  std::vector<double> call_demand_[2], split_demand_[kSplitKinds];
  std::vector<SplitRecord> split_tiles_[kSplitKinds];
  SplitRecord split_[kSplitKinds];
};

}  // namespace vrlis
