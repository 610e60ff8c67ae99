#include "vrlis_integration/effort_price.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vrlis::integration {

namespace {

// The mean of the values with the largest thousandth left out (a few fireflies must not flip
// decisions); 0 for none.
double TrimmedMean(std::vector<double> values) {
  if (values.empty()) return 0;
  const std::size_t kept = values.size() - values.size() / 1000;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(kept) - 1, values.end());
  double sum = 0;
  for (std::size_t k = 0; k < kept; ++k) sum += values[k];
  return sum / double(kept);
}

// The variance of one pass's pixel values: half the squared difference of horizontal
// neighbours (x and x + 1, x even; it overstates the variance at edges), the mean over the
// pairs with the largest thousandth left out; of the pairs whose first pixel `use` flags, if given.
double NeighbourVariance(const std::vector<double>& values, int width, int height,
                         const std::vector<bool>* use = nullptr) {
  std::vector<double> pairs;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x + 1 < width; x += 2) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      if (use && !(*use)[i]) continue;
      const double d = values[i] - values[i + 1];
      pairs.push_back(d * d / 2);
    }
  return TrimmedMean(pairs);
}

}  // namespace

EffortPrice::EffortPrice(int width, int height)
    : width_(width),
      height_(height),
      pixels_(static_cast<std::size_t>(width) * height),
      tiles_x_((width + kTile - 1) / kTile) {
  for (Passes& p : passes_of_) p.sum.resize(pixels_), p.sum_sq.resize(pixels_);
  const std::size_t tiles = static_cast<std::size_t>(tiles_x_) * ((height + kTile - 1) / kTile);
  for (int kind = 0; kind < 2; ++kind) {
    tiles_[kind].resize(tiles);
    call_demand_[kind].assign(tiles, 1.0);
    for (auto& part : pass_tiles_[kind]) part.resize(tiles);
  }
  remainder_tiles_.resize(tiles);
  remainder_demand_.assign(tiles, 1.0);
  pass_remainder_.resize(tiles);
}

EffortPrice::PixelStats& EffortPrice::BeginPass() {
  pass_.medium.resize(pixels_), pass_.surface.resize(pixels_), pass_.remainder.resize(pixels_);
  return pass_;
}

void EffortPrice::Add(const Film& pass, double pixel_work) {
  const std::vector<EffortStats>& medium = pass_.medium;
  const std::vector<EffortStats>& surface = pass_.surface;
  const std::vector<RemainderStats>& remainder = pass_.remainder;
  Passes& into = passes_of_[passes_ >= kMinPasses];
  const std::vector<EffortStats>* stats[2] = {&medium, &surface};
  // Each pixel's stats added once, into its tile's sums of the pass (a pass's adds are a
  // sizeable part of a short pass, and they run on one thread); the tiles' into the rest.
  for (std::size_t i = 0; i < pixels_; ++i) {
    const std::size_t tile = Tile(static_cast<int>(i) % width_, static_cast<int>(i) / width_);
    pass_remainder_[tile] += remainder[i];
    for (int kind = 0; kind < 2; ++kind) {
      const EffortStats& p = (*stats[kind])[i];
      if (!(p.calls > 0)) continue;  // then every field is 0
      const bool decided = price_[kind] > 0 && p.decided > 0;  // the first pass takes every gather once
      pass_tiles_[kind][decided][tile] += p;
      ++into.called[kind];
      if (decided) ++into.decided[kind];
    }
  }
  EffortStats total[2];
  for (std::size_t tile = 0; tile < pass_remainder_.size(); ++tile) {
    const RemainderStats r = std::exchange(pass_remainder_[tile], {});
    remainder_ += r;
    remainder_tiles_[tile] += r;
    for (int kind = 0; kind < 2; ++kind)
      for (int decided = 0; decided < 2; ++decided) {
        const EffortStats p = std::exchange(pass_tiles_[kind][decided][tile], {});
        total[kind] += p;
        tiles_[kind][tile] += p;
        if (price_[kind] > 0) (decided ? decided_ : undecided_)[kind] += p;
      }
  }
  for (int kind = 0; kind < 2; ++kind) {
    const EffortStats& t = total[kind];
    into.switchable[kind] += t.rule_samples + t.cheapest_samples + t.mixture_samples;
    into.cheapest[kind] += t.cheapest_samples, into.mixture[kind] += t.mixture_samples;
  }
  for (std::size_t i = 0; i < pixels_; ++i) {
    const double v = std::sqrt(pass.pixels[i].MeanSquare());
    if (!std::isfinite(v)) continue;
    into.sum[i] += v;
    into.sum_sq[i] += v * v;
  }
  if (total[0].pair_pixel > 0 && width_ >= 2) {  // the medium gathers' pairs: one estimator on both images
    std::vector<double> rendered(pixels_), accurate(pixels_);
    std::vector<bool> paired(pixels_);
    for (std::size_t i = 0; i < pixels_; ++i) {
      rendered[i] = std::sqrt(pass.pixels[i].MeanSquare());
      accurate[i] = std::sqrt((pass.pixels[i] + medium[i].pair_delta).MeanSquare());
      paired[i] = medium[i].pair_pixel > 0 && i % static_cast<std::size_t>(width_) + 1 < static_cast<std::size_t>(width_) &&
                  medium[i + 1].pair_pixel > 0;
    }
    // The paired pixels' accurate image against the whole rendered one, the first price's
    // estimate: over the paired pixels alone the rendered image's rare large samples, which
    // the accurate image lacks, make the difference's noise.
    const double change = NeighbourVariance(accurate, width_, height_, &paired) - NeighbourVariance(rendered, width_, height_);
    if (std::isfinite(change)) accurate_change_ = change;
  }
  into.pixel_work += pixel_work;
  ++into.count;
  for (int kind = 0; kind < 2; ++kind) {
    gathers_[kind] += total[kind];
    (price_[kind] > 0 ? controlled_ : uncontrolled_)[kind] += total[kind];
  }
  ++passes_;
  if (passes_ >= kMinPasses) Refresh();
}

void EffortPrice::Refresh() {
  const Passes& p = measured();
  const double n = p.count;
  double variance = 0;
  if (n >= 2) {
    std::vector<double> pixels(pixels_);
    for (std::size_t i = 0; i < pixels_; ++i) {  // each pixel's variance over the passes
      double mean = p.sum[i] / n;
      pixels[i] = std::max(0.0, (p.sum_sq[i] - n * mean * mean) / (n - 1));
    }
    variance = TrimmedMean(std::move(pixels));  // the mean over pixels of their variance
  } else {
    if (width_ < 2) return;
    variance = NeighbourVariance(p.sum, width_, height_);
  }
  const double pixel_cost = p.pixel_work / (n * double(pixels_));
  variance_ = variance, pixel_cost_ = pixel_cost;
  for (int kind = 0; kind < 2; ++kind) {
    const EffortStats& g = gathers_[kind];
    const EffortStats& u = uncontrolled_[kind];
    const EffortStats& c = controlled_[kind];
    // One gather's cost, its decision's included, from the passes that took every gather once
    // (the controlled passes charge the decisions of the gathers not taken to those taken, a
    // feedback), scaled to the models the controlled passes chose by their sampling work.
    auto sampling = [](const EffortStats& s) { return s.gathers > 0 ? s.sample_work / double(s.gathers) : 0.0; };
    const double models = sampling(c) > 0 && sampling(u) > 0 ? sampling(c) / sampling(u) : 1;
    const double gather_cost = u.gathers > 0 ? models * u.work / double(u.gathers) : 0;
    const double calibration = g.predicted > 0 ? g.measured / g.predicted : 0;
    price_[kind] = variance > 0 && gather_cost > 0 && calibration > 0
                       ? calibration * pixel_cost / (variance * gather_cost)
                       : 0;
  }
  for (int kind = 0; kind < 2; ++kind) {
    weighing_[kind] = WeighModels(kind);
    model_[kind] = Model(kind, weighing_[kind]);
    decisions_pay_[kind] = DecisionsPay(kind);
    for (std::size_t tile = 0; tile < call_demand_[kind].size(); ++tile) call_demand_[kind][tile] = CallDemand(kind, tile);
  }
  for (std::size_t tile = 0; tile < remainder_demand_.size(); ++tile) remainder_demand_[tile] = RemainderDemand(tile);
}

double EffortPrice::RemainderDemand(std::size_t t) const {
  const RemainderStats& tile = remainder_tiles_[t];
  constexpr double kFewPaths = 16;  // below which a tile's cost is too noisy
  const RemainderStats& counted = tile.paths >= kFewPaths ? tile : remainder_;
  const double cost = counted.paths > 0 ? counted.work / counted.paths : 0;
  if (!(value_of_time() > 0) || !(cost > 0) || !(tile.launches > 0)) return 1;
  return std::sqrt(tile.m2 / tile.launches / cost * value_of_time());
}

EffortPrice::ModelWeighing EffortPrice::WeighModels(int k) const {
  ModelWeighing w;
  const EffortStats& all = gathers_[k];
  // The models' work per sample from the first passes only, where each took every gather
  // once in whole batches: a controlled pass takes the image's model in the small batches
  // roulette leaves, at a higher cost per sample that the others, not taken, never show.
  const EffortStats& pilot = uncontrolled_[k];
  const Passes& p = measured();
  const double switchable = p.switchable[k];
  if (!(all.rule_samples > all.mixture_measured && pilot.rule_samples > pilot.mixture_measured && switchable > 0 &&
        variance_ > 0 && pixel_cost_ > 0))
    return w;
  // Per pixel and pass, what a model changes against the rule were every sample below the
  // accurate tier taken with it: the variance it adds (estimated from the rule's samples) and
  // its work over the rule's; and its share of those samples in the measured passes.
  const double samples = switchable / (p.count * double(pixels_));
  const double rule_work = pilot.rule_work / (pilot.rule_samples - pilot.mixture_measured);
  auto change = [&](ModelChange& c, double excess, double measured, double taken, double work, double share) {
    if (!(measured > 0 && taken > 0)) return;
    c.dv = samples * excess / measured, c.dt = samples * (work / taken - rule_work), c.share = share, c.known = true;
  };
  change(w.cheapest, all.cheapest_excess, all.rule_samples, pilot.cheapest_samples, pilot.cheapest_work,
         p.cheapest[k] / switchable);
  change(w.mixture, all.mixture_excess, all.mixture_measured, pilot.mixture_samples, pilot.mixture_work,
         p.mixture[k] / switchable);
  // The accurate model's variance from the pairs' image (of the medium gathers only; in the
  // first priced refresh only), its work from the pairs' own. The pairs' image is against
  // the first pass's, whose pilots took the cheapest model and the mixture: the accurate
  // model's change against the rule adds theirs.
  if (k == static_cast<int>(GatherKind::Medium) && passes_ == kMinPasses && !std::isnan(accurate_change_) &&
      all.accurate_samples > 0)
    w.accurate = {vrlis::EffortModel::Accurate,
                  accurate_change_ + w.cheapest.share * w.cheapest.dv + w.mixture.share * w.mixture.dv,
                  samples * (all.accurate_work / all.accurate_samples - rule_work), 0, true};
  // The measured variance and cost are of a mix, each model's share of the samples with its
  // change and the rest with the rule's: the states compared whole, not to first order (one
  // model for the whole image is no small change).
  w.v_rule = variance_, w.t_rule = pixel_cost_;
  for (const ModelChange* c : {&w.cheapest, &w.mixture, &w.accurate}) w.v_rule -= c->share * c->dv, w.t_rule -= c->share * c->dt;
  return w;
}

vrlis::EffortModel EffortPrice::Model(int k, const ModelWeighing& w) const {
  using vrlis::EffortModel;
  // The accurate model is weighed once, at the first price, from the first passes' pairs
  // (pair()): the one comparison of it with the rule by one estimator on the same queries. The
  // passes after measure the model they take only, and a render that changes between the two,
  // or unlike another render of the scene, pays for the change (docs/maths.md#effort-accurate).
  if (model_[k] == EffortModel::Accurate) return EffortModel::Accurate;
  if (!(w.v_rule > 0 && w.t_rule > 0)) return EffortModel::Chosen;  // none, or estimates that contradict the measurement
  // The accurate model is taken where it pays its margin (kAccurateMargin).
  auto score = [](const ModelChange& c, double product) {
    return c.model == EffortModel::Accurate ? product / kAccurateMargin : product;
  };
  EffortModel best = EffortModel::Chosen;
  double least = w.v_rule * w.t_rule;
  for (const ModelChange* c : {&w.cheapest, &w.mixture, &w.accurate}) {
    const double v = w.v_rule + c->dv, product = v * (w.t_rule + c->dt);
    if (c->known && v > 0 && score(*c, product) < least) least = score(*c, product), best = c->model;
  }
  return best;
}

bool EffortPrice::DecisionsPay(int k) const {
  const EffortStats& d = decided_[k];
  const EffortStats& once = undecided_[k];
  const double decided_pixels = passes_of_[1].decided[k];  // the pixels in decided_
  if (!(decided_pixels > 0 && variance_ > 0 && pixel_cost_ > 0)) return true;
  // Per pixel that decided, the variance its decisions added (negative: removed) and their
  // work against the same VRLs each taken once: the work outside sampling less the
  // undecided calls' per VRL (0 before any: it then overstates the decisions' cost until the
  // first undecided pass), and the samples' over one per VRL at the work of a sample (of
  // the first pass's while none was decided); over the image, times the share of pixels
  // that gather.
  const EffortStats& counted = d.gathers > 0 ? d : uncontrolled_[k];
  const double sample_cost = counted.gathers > 0 ? counted.sample_work / double(counted.gathers) : 0;
  const double loop = once.vrls > 0 ? (once.work - once.sample_work) / once.vrls : 0;
  const double work = (d.work - d.sample_work) - d.vrls * loop + (double(d.gathers) - d.vrls) * sample_cost;
  const Passes& p = measured();
  const double scale = p.called[k] / (p.count * double(pixels_)) / decided_pixels;
  const double dv = scale * (d.roulette_excess + within(GatherKind(k)) * d.split_excess), dt = scale * work;
  // The measured variance and cost are of a mixture, the decided share of the pixels with
  // the decisions' change, the rest without: the two states' products compared whole, not
  // to first order (turning the decisions off is no small change).
  const double decided_share = p.called[k] > 0 ? p.decided[k] / p.called[k] : 0;
  const double v_once = variance_ - decided_share * dv, t_once = pixel_cost_ - decided_share * dt;
  if (!(v_once > 0)) return true;   // the variance they add estimated above the whole: keep them
  if (!(t_once > 0)) return false;  // the time they take estimated above the whole
  return (v_once + dv) * (t_once + dt) < v_once * t_once;
}

double EffortPrice::CallDemand(int kind, std::size_t t) const {
  const EffortStats& tile = tiles_[kind][t];
  const EffortStats& all = gathers_[kind];
  // A taken call's decisions: their time is what a call not taken saves.
  auto decisions = [](const EffortStats& s) { return (s.work - s.sample_work) / s.call_rate; };
  constexpr double kFewCalls = 16;  // taken calls below which a tile's cost is too noisy
  const double cost = tile.call_rate >= kFewCalls ? decisions(tile) : all.call_rate > 0 ? decisions(all) : 0;
  if (!(value_of_time() > 0) || !(cost > 0) || !(tile.calls > 0)) return 1;
  return std::sqrt(tile.call_m2 / tile.calls / cost * value_of_time());
}

}  // namespace vrlis::integration
