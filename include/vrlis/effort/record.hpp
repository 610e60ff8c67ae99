#pragma once
// What a pixel's gather calls tell the effort price in a pass (price.hpp): each call adds to
// an EffortRecord, from the contributions its visitor returns and its counted work (work.hpp).
// Plain sums, so that records of pixels, tiles and passes add (docs/maths.md#effort-price).
#include "policy.hpp"

namespace vrlis {

struct EffortRecord {
  // Of the calls: how many, how many decided their gathers one by one, the VRLs they held,
  // the sum of their rates (EffortCallRate) and of rate x (contribution)^2, an estimate of
  // their second moments had each been taken (docs/maths.md#effort-calls).
  double calls = 0, decided = 0, vrls = 0, call_rate = 0, call_m2 = 0;
  // Of the samples (effort weight w, unweighted contribution y): how many, the sums of w y and
  // of (w y)^2 (given the paths, a bound of the calls' variance: EffortPrice::EndProbe); of the
  // decided calls' samples the predicted second moments (w x bound)^2 / q and the
  // measured w y^2 (their ratio calibrates the price), and w y^2 (w - 1) over the rouletted
  // (w > 1) and the split (w < 1): the variance the decisions add and remove against one
  // sample each (docs/maths.md#effort-decide); of the gathers split into several samples,
  // their within variances and second moments, each from its own samples.
  double samples = 0, sum = 0, sum_sq = 0, predicted = 0, measured = 0;
  double roulette_excess = 0, split_excess = 0, split_within = 0, split_second = 0;
  // Of `auto`'s rule's samples: (w y)^2 (over_equiangular - 1) and (w y)^2 (over_mixture - 1),
  // the variance the pixel would gain had they taken the cheapest model or the mixture, and
  // how many measured the mixture (docs/maths.md#effort-models).
  double cheapest_excess = 0, mixture_excess = 0, mixture_measured = 0;
  // Per EffortModel, the samples and their sampling work (the rule's only from calls that did
  // not measure the mixture); the calls' whole work, and that of sampling and visiting (the
  // rest is the decisions': the loop and the bounds).
  double model_samples[kEffortModels] = {}, model_work[kEffortModels] = {};
  double work = 0, sample_work = 0;

  EffortRecord& operator+=(const EffortRecord& o) {
    calls += o.calls, decided += o.decided, vrls += o.vrls, call_rate += o.call_rate, call_m2 += o.call_m2;
    samples += o.samples, sum += o.sum, sum_sq += o.sum_sq, predicted += o.predicted, measured += o.measured;
    roulette_excess += o.roulette_excess, split_excess += o.split_excess;
    split_within += o.split_within, split_second += o.split_second;
    cheapest_excess += o.cheapest_excess, mixture_excess += o.mixture_excess, mixture_measured += o.mixture_measured;
    for (int m = 0; m < kEffortModels; ++m) model_samples[m] += o.model_samples[m], model_work[m] += o.model_work[m];
    work += o.work, sample_work += o.sample_work;
    return *this;
  }
};

// The sub-estimators a renderer samples itself and splits by the price
// (docs/maths.md#effort-split): our renderer's path-traced remainder, and its VPL connections
// gathered along camera segments in the medium and at surfaces.
enum class SplitKind { Remainder, VplMedium, VplSurface };
inline constexpr int kSplitKinds = 3;

// One kind's launches (the points it started from), the samples they took, their counted work,
// and the sum over the launches of what one sample adds to a launch's variance that splitting
// divides: the remainder's second moment of one path (its paths share nothing but their
// start; per path (contribution)^2 / rate, unbiased whatever the rate), the VPL connections'
// variance within their gather (they share the pass's VPLs; the connections' sample variance).
struct SplitRecord {
  double launches = 0, samples = 0, work = 0, m2 = 0;
  SplitRecord& operator+=(const SplitRecord& o) {
    launches += o.launches, samples += o.samples, work += o.work, m2 += o.m2;
    return *this;
  }
};

// One pixel's records in a pass: its medium-to-medium and medium-to-surface calls, the
// statistics-only calls that gathered its medium VRLs again under the accurate model
// (EffortPrice::Pairs), and its split sub-estimators (by SplitKind).
struct PixelRecord {
  EffortRecord medium, surface, pair;
  SplitRecord split[kSplitKinds];
  SplitRecord& operator[](SplitKind k) { return split[static_cast<int>(k)]; }
};

}  // namespace vrlis
