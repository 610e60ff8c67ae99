#pragma once
// Every VRL against one camera segment, or one surface point, in one call: the query's
// shared parts validated and the samplers chosen once, the effort decision per VRL
// (effort/policy.hpp), the gathers run in batches by SampleMediumGathers / SampleSurfaceGathers,
// and each sample handed to the renderer, which traces its occlusion ray:
//
//   vrlis::GatherMediumVrls(method, effort, camera, medium, vrls, weights, n, uniform,
//       [&](int i, const vrlis::GatherSample<float>& s, float w) {
//         if (s.contributes() && visible(s.camera_point, s.light_point)) sum += w * s.weight * flux[i];
//       });
//
// weights[i] >= 0 scales VRL i's predicted contribution (its power times the camera path's
// throughput, in the units of the price): for the effort control's decisions, and with
// VrlMarginal as step one for the choice of the gathers it fits
// (EffortSettings::marginal_threshold, with the control on or off); null: all equal. uniform()
// returns a number in [0, 1). With the control off, or the call's gathers undecided
// (EffortSettings::decide), every VRL draws exactly its gather's numbers (two, or one at a
// surface), in order, valid or not, so images do not depend on batching or validity; decided,
// the call may first draw one for whether it is taken (EffortCallRate), and each VRL one for
// its number of samples.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <vector>

#include "../effort/marginal_fits.hpp"
#include "../effort/policy.hpp"
#include "../effort/work.hpp"
#include "medium_gather.hpp"
#include "surface_gather.hpp"

namespace vrlis {
namespace detail {

// T where a parameter must not take part in deducing it (so that a null pointer of weights
// passes: Real comes from the segments).
template <typename T>
struct NonDeduced {
  using type = T;
};

// Samples of VRLs waiting for their batched gather: VRL index, effort weight, numbers.
template <typename Real, int kUniforms>
struct GatherBatch {
  // Several lanes' worth, so that a split gather's samples mostly share one fit.
  static constexpr int kSize = kGatherChunk;
  VrlSegment<Real> segments[kSize];
  Real u[kUniforms][kSize];
  int source[kSize];
  Real effort_weight[kSize];
  int count = 0;
};

// The work of a call's decisions per VRL (work.hpp): its quick and its tight bound.
struct BoundWork {
  double quick, tight;
};

// The loop shared by both gathers: bounds(first, n, quick, tight) writes, for VRLs
// [first, first + n) (n <= kBoundBatch), a cheap bound of each one's unweighted mean into
// quick and a tighter one into tight, each if set (bounds.hpp, in vector lanes); the quick one
// decides alone where it already puts q at the floor (the tighter bound would too), and a
// block's tight ones are taken once one of its VRLs needs them. gather(model, batch, samples)
// samples a batch with the EffortModel's samplers (always Chosen unless kPolicy), one batch
// per model, and returns its counted work. A batch is run when full; with the gathers
// undecided (the control off, or EffortSettings::decide false) also after every kSize VRLs,
// so that the batches are those of one gather per VRL (decided, the few samples roulette
// leaves would each pay a whole batch). The tally, if set, counts the work of the loop, the
// bounds and the batches.
template <int kUniforms, bool kPolicy, typename Real, typename Uniform, typename Bounds, typename Gather,
          typename Connect>
void GatherEachVrl(const EffortSettings& effort, const VrlSegment<Real>* vrls, const Real* weights,
                   int count, bool valid, Uniform& uniform, BoundWork bound_work, Bounds&& bounds, Gather&& gather,
                   Connect& connect, EffortTally* tally) {
  const double rate = EffortCallRate(effort);
  if (tally) tally->work += work_costs::kVrl;  // a call not taken still draws its number
  if (rate < 1 && !(double(uniform()) < rate)) return;  // each sample of a taken call weighs 1 / rate more
  using Batch = GatherBatch<Real, kUniforms>;
  // By EffortModel, each built when first used (they are zeroed, and a call uses one or two).
  std::optional<Batch> batches[kPolicy ? kEffortModels : 1];
  auto batch_of = [&](EffortModel model) -> Batch& {
    std::optional<Batch>& batch = batches[static_cast<int>(model)];
    if (!batch) batch.emplace();
    return *batch;
  };
  GatherSample<Real> samples[Batch::kSize];  // once per call: every batch overwrites them
  auto run = [&](EffortModel model) {
    Batch& batch = *batches[static_cast<int>(model)];
    const double work = gather(model, batch, samples);
    for (int k = 0; k < batch.count; ++k) connect(batch.source[k], samples[k], batch.effort_weight[k]);
    if (tally) {
      tally->model_samples[static_cast<int>(model)] += static_cast<std::uint64_t>(batch.count);
      tally->model_work[static_cast<int>(model)] += work;
      tally->sample_work += work;
      tally->work += work;
    }
    batch.count = 0;
  };
  Real quick[kBoundBatch], tight[kBoundBatch];
  bool tight_taken = false;  // for the block of VRL i
  const bool decide = effort.on && effort.decide;
  EffortModel model = EffortModel::Chosen;  // the call's, unless decided per gather
  if constexpr (kPolicy) model = ChooseEffortModel(effort, 1);
  double loop_work = count * work_costs::kVrl;
  for (int i = 0; i < count; ++i) {
    const bool usable = valid && Validate(vrls[i]) == QueryError::None;
    const int lane = i % kBoundBatch, first = i - lane, block = std::min(kBoundBatch, count - first);
    if (decide && lane == 0) {
      bounds(first, block, quick, nullptr), tight_taken = false;
      loop_work += block * (bound_work.quick + work_costs::kDecision);
    }
    int n = 1;
    Real weight = 1;
    if (decide) {
      const double weight_i = weights ? double(weights[i]) : 1;  // null: all equal
      double m2 = -1;  // the predicted second moment, once needed
      auto predicted = [&] {
        if (!tight_taken) {
          bounds(first, block, nullptr, tight), tight_taken = true;
          loop_work += block * bound_work.tight;
        }
        if (m2 < 0) m2 = usable ? Sqr(weight_i * double(tight[lane])) : 0;
        return m2;
      };
      double demand = EffortDemand(effort, usable ? Sqr(weight_i * double(quick[lane])) : 0);
      if (demand > effort.floor) demand = EffortDemand(effort, predicted());
      const double q = EffortClamp(effort, demand);  // overall; q / rate within a taken call
      if constexpr (kPolicy) model = ChooseEffortModel(effort, demand);
      n = EffortSamples(q / rate, double(uniform()));
      weight = n > 0 ? Real(1 / q) : Real(0);
      if (tally && n > 0) tally->predicted += n * predicted() / q;
    }
    Batch& batch = batch_of(model);
    for (int j = 0; j < n; ++j) {
      Real u[kUniforms];
      for (Real& x : u) x = uniform();
      if (!usable) continue;
      if (batch.count == Batch::kSize) run(model);
      batch.segments[batch.count] = vrls[i];
      for (int k = 0; k < kUniforms; ++k) batch.u[k][batch.count] = u[k];
      batch.source[batch.count] = i;
      batch.effort_weight[batch.count++] = weight;
    }
    if (!decide && (i + 1) % Batch::kSize == 0 && batch.count > 0) run(model);
  }
  for (int m = 0; m < (kPolicy ? kEffortModels : 1); ++m)
    if (batches[m] && batches[m]->count > 0) run(EffortModel(m));
  if (tally) tally->work += loop_work;
}

}  // namespace detail

// The segment sampler that `method` takes under the effort control's model (EffortModel,
// ChooseEffortModel): `auto`'s rule, or in its place the accurate, the cheapest or the
// mixture's sampler; any other sampler is its own. Also for a renderer's point-and-line
// gathers that the control does not price (VPLs seen from a camera segment), which then
// follow the medium-to-surface gathers' model: the same query.
inline SegmentChoice SegmentSamplerFor(SegmentChoice method, EffortModel model) {
  if (method != SegmentSamplers::Of<AutoEntry>()) return method;
  switch (model) {
    case EffortModel::Accurate: return SegmentSamplers::Of<FullProductEntry>();
    case EffortModel::Cheapest: return SegmentSamplers::Of<EquiangularEntry>();
    case EffortModel::Mixture: return SegmentSamplers::Of<CauchyMixtureEntry>();
    case EffortModel::Chosen: break;
  }
  return method;
}

// The medium-to-medium gathers of vrls[0, count) against the camera segment:
// connect(i, sample, effort_weight) for every sample taken (an invalid query takes none);
// tally, if set, adds the predictions (decided gathers only) and the call's counted work;
// marginal_scores, if set and VrlMarginal is step one, the gathers' MarginalFitScores.
template <typename Real, typename Uniform, typename Connect>
void GatherMediumVrls(GatherSamplers method, const EffortSettings& effort, const RaySegment<Real>& camera,
                      const Medium<Real>& medium, const VrlSegment<Real>* vrls,
                      const typename detail::NonDeduced<Real>::type* weights, int count,
                      Uniform&& uniform, Connect&& connect, EffortTally* tally = nullptr,
                      ScoreOctaves* marginal_scores = nullptr) {
  const bool valid = Validate(camera) == QueryError::None && Validate(medium) == QueryError::None;
  WithGatherSamplers<Real>(method, [&](auto step_one, auto step_two) {
    using VrlSampler = typename decltype(step_one)::type;
    using StepTwo = typename decltype(step_two)::type;
    constexpr bool policy = std::is_same_v<StepTwo, AutoEntry::Sampler<Real>>;
    // VrlMarginal's fits for the gathers whose score reaches the threshold (not auto's
    // accurate model, which is already given by demand).
    constexpr bool marginal = std::is_same_v<VrlSampler, VrlMarginalEntry::Sampler<Real>>;
    const bool chosen = marginal && valid && effort.marginal_threshold > 0;
    const bool scored = marginal && valid && (chosen || marginal_scores);
    constexpr int kStackScores = 256;
    double stack_score[marginal ? kStackScores : 1];
    Real stack_bound[marginal ? kStackScores : 1];
    std::vector<double> heap_score;
    std::vector<Real> heap_bound;
    double* score = stack_score;
    Real* bound = stack_bound;
    if (scored) {
      if (count > kStackScores) {
        heap_score.resize(std::size_t(count)), score = heap_score.data();
        heap_bound.resize(std::size_t(count)), bound = heap_bound.data();
      }
      detail::WithWidestLanes([&] { MarginalFitScores(camera, medium, vrls, weights, count, bound, score); });
      if (tally) tally->work += count * work_costs::kMediumTightBound;
      for (int i = 0; marginal_scores && i < count; ++i) marginal_scores->Add(score[i]);
    }
    detail::GatherEachVrl<2, policy>(
        effort, vrls, weights, count, valid, uniform,
        // The tight bounds taken with the scores are counted there.
        detail::BoundWork{work_costs::kMediumQuickBound, scored ? 0 : work_costs::kMediumTightBound},
        [&](int first, int n, Real* quick, Real* tight) {
          if (scored && tight) {  // taken with the scores
            std::copy(bound + first, bound + first + n, tight);
            tight = nullptr;
          }
          if (quick || tight) MediumGatherBounds(camera, vrls + first, n, medium, quick, tight);
        },
        [&](EffortModel model, const auto& b, GatherSample<Real>* samples) {
          const SegmentChoice taken = SegmentSamplerFor(method.segment, model);
          // Its counted work: each sample's, VrlMarginal's fit where it takes one.
          auto with = [&](auto one, auto two, const bool* fitted = nullptr) {
            using One = typename decltype(one)::type;
            SampleMediumGathers<One, typename decltype(two)::type>(ValidQuery{}, camera, medium, b.segments, b.count,
                                                                  b.u[0], b.u[1], samples, effort.measure_mixture,
                                                                  true, fitted);
            int fits = 0;
            if constexpr (std::is_same_v<One, VrlMarginalEntry::Sampler<Real>>)
              for (int k = 0; k < b.count; ++k) fits += !fitted || fitted[k];
            return b.count * (MediumSampleWork(taken) + (effort.measure_mixture ? work_costs::kMixtureDensity : 0)) +
                   fits * MarginalFitWork();
          };
          // A model in place of auto's rule: its segment sampler, after VrlMarginal for the
          // accurate one and VrlPoint for the others.
          if constexpr (policy) {
            if (model != EffortModel::Chosen)
              return SegmentSamplers::WithEntry(taken, [&](auto entry) {
                using Two = Type<typename decltype(entry)::template Sampler<Real>>;
                if (model == EffortModel::Accurate) return with(Type<VrlMarginalEntry::Sampler<Real>>{}, Two{});
                return with(Type<VrlPointEntry::Sampler<Real>>{}, Two{});
              });
          }
          bool fitted[std::decay_t<decltype(b)>::kSize];
          for (int k = 0; chosen && k < b.count; ++k) fitted[k] = score[b.source[k]] >= effort.marginal_threshold;
          return with(Type<VrlSampler>{}, Type<StepTwo>{}, chosen ? fitted : nullptr);
        },
        connect, tally);
  });
}

// The medium-to-surface gathers of vrls[0, count) at the point (normal facing the viewer),
// the VRL points by `method`'s camera sampler, as GatherMediumVrls.
template <typename Real, typename Uniform, typename Connect>
void GatherSurfaceVrls(SegmentChoice method, const EffortSettings& effort, Vec3<Real> point, Vec3<Real> normal,
                       const Medium<Real>& medium, const VrlSegment<Real>* vrls,
                       const typename detail::NonDeduced<Real>::type* weights, int count,
                       Uniform&& uniform, Connect&& connect, EffortTally* tally = nullptr) {
  const bool valid = ValidateSurfacePoint(point, normal) == QueryError::None && Validate(medium) == QueryError::None;
  SegmentSamplers::WithEntry(method, [&](auto entry) {
    using Sampler = typename decltype(entry)::template Sampler<Real>;
    constexpr bool policy = std::is_same_v<Sampler, AutoEntry::Sampler<Real>>;
    detail::GatherEachVrl<1, policy>(
        effort, vrls, weights, count, valid, uniform,
        detail::BoundWork{work_costs::kSurfaceQuickBound, work_costs::kSurfaceTightBound},
        [&](int first, int n, Real* quick, Real* tight) {
          SurfaceGatherBounds(point, normal, vrls + first, n, medium, quick, tight);
        },
        [&](EffortModel model, const auto& b, GatherSample<Real>* samples) {
          const SegmentChoice taken = SegmentSamplerFor(method, model);
          auto with = [&](auto sampler) {
            SampleSurfaceGathers<typename decltype(sampler)::type>(ValidQuery{}, point, normal, medium, b.segments,
                                                                   b.count, b.u[0], samples, effort.measure_mixture);
            return b.count * (SurfaceSampleWork(taken) + (effort.measure_mixture ? work_costs::kMixtureDensity : 0));
          };
          if constexpr (policy) {
            if (model != EffortModel::Chosen)
              return SegmentSamplers::WithEntry(taken, [&](auto entry) {
                return with(Type<typename decltype(entry)::template Sampler<Real>>{});
              });
          }
          return with(Type<Sampler>{});
        },
        connect, tally);
  });
}

}  // namespace vrlis
