#pragma once
// Every VRL against one camera segment, or one surface point, in one call: the query's
// shared parts validated and the samplers chosen once, the effort decision per VRL
// (effort/policy.hpp), the gathers run in batches by SampleMediumGathers / SampleSurfaceGathers,
// and each sample handed to the renderer's visitor, which traces its occlusion ray:
//
//   vrlis::GatherMediumVrls(samplers, camera, medium, vrls, n, uniform,
//       [&](int i, const vrlis::GatherSample<float>& s, float w) {
//         if (s.contributes() && visible(s.camera_point, s.light_point)) sum += w * s.weight * flux[i];
//       });
//
// With an EffortCall (effort/call.hpp; EffortPrice::Pixel hands them out) the call is
// controlled and, with a record, learns: the visitor then returns the contribution it added.
// uniform() returns a number in [0, 1). With the control off, or the call's gathers
// undecided (EffortSettings::decide), every VRL draws exactly its gather's numbers (two, or
// one at a surface), in order, valid or not, so images do not depend on batching or
// validity; decided, the call may first draw one for whether it is taken (EffortCallRate),
// and each VRL one for its number of samples (docs/porting.md#the-fast-path).
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "../effort/call.hpp"
#include "../effort/work.hpp"
#include "medium_gather.hpp"
#include "surface_gather.hpp"

namespace vrlis {
namespace detail {

// T where a parameter must not take part in deducing it (so that an EffortCall given as
// braces passes: Real comes from the segments).
template <typename T>
struct NonDeduced {
  using type = T;
};

// Whether a call of rate `rate` (EffortCallRate) is taken at its first number u.
inline bool CallTakenAt(double rate, double u) { return !(rate < 1) || u < rate; }

// Whether a medium call with VrlMarginal as step one (`marginal`) scores its VRLs, which it
// does before deciding whether it is taken (a valid query's; the fits' threshold, or a renderer
// collecting the scores).
template <typename Real>
bool ScoresVrls(bool marginal, const EffortCall<Real>& call) {
  return marginal && (call.settings.marginal_threshold > 0 || call.scores);
}

// The camera sampler of a surface gather's samplers, and a call of f(Entry{}) with its entry:
// chosen at run time, or fixed at compile time (that entry alone compiled).
inline SegmentChoice CameraSamplerOf(SegmentChoice c) { return c; }
inline SegmentChoice CameraSamplerOf(GatherSamplers s) { return s.segment; }
template <typename Camera, typename Vrl>
constexpr SegmentChoice CameraSamplerOf(FixedSamplers<Camera, Vrl>) { return SegmentSamplers::Of<Camera>(); }
template <typename F>
decltype(auto) WithCameraSampler(SegmentChoice c, F&& f) { return SegmentSamplers::WithEntry(c, f); }
template <typename F>
decltype(auto) WithCameraSampler(GatherSamplers s, F&& f) { return SegmentSamplers::WithEntry(s.segment, f); }
template <typename Camera, typename Vrl, typename F>
decltype(auto) WithCameraSampler(FixedSamplers<Camera, Vrl>, F&& f) { return f(Camera{}); }

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

// The work of a call's decisions per VRL (work.hpp): its quick and its tight bound, and what
// the call spent on every VRL before its loop (VrlMarginal's scores).
struct BoundWork {
  double quick, tight, before = 0;
};

// A decided call's samples of each VRL (a gather split into several samples): how many, and
// the sums of their unweighted contributions and squares, for the record's within variance.
struct SplitSums {
  int samples;
  double sum, sum_sq;
};

// Whether visit(i, sample, weight) returns the contribution it added (what a record needs).
template <typename Visit, typename Real>
inline constexpr bool kVisitReturns =
    !std::is_void_v<std::invoke_result_t<Visit&, int, const GatherSample<Real>&, Real>>;

// The loop shared by both gathers: bounds(first, n, quick, tight) writes, for VRLs
// [first, first + n) (n <= kBoundBatch), a cheap bound of each one's unweighted mean into
// quick and a tighter one into tight, each if set (bounds.hpp, in vector lanes); the quick one
// decides alone where it already puts q at the floor (the tighter bound would too), and a
// block's tight ones are taken once one of its VRLs needs them. gather(model, batch, samples)
// samples a batch with the EffortModel's samplers (always Chosen unless kPolicy), one batch
// per model, and returns its counted work. A batch is run when full; with the gathers
// undecided (the control off, or EffortSettings::decide false) also after every kSize VRLs,
// so that the batches are those of one gather per VRL (decided, the few samples roulette
// leaves would each pay a whole batch). The call's record, if set, adds what the visitor's
// contributions and the counted work of the loop, the bounds, the batches and the visits tell
// (record.hpp).
template <int kUniforms, bool kPolicy, typename Real, typename Uniform, typename Bounds, typename Gather,
          typename Visit>
void GatherEachVrl(const EffortCall<Real>& call, const VrlSegment<Real>* vrls, int count, bool valid,
                   Uniform& uniform, BoundWork bound_work, Bounds&& bounds, Gather&& gather, Visit& visit) {
  constexpr bool kReturns = kVisitReturns<Visit, Real>;
  const EffortSettings& effort = call.settings;
  EffortRecord* record = kReturns ? call.record : nullptr;
  if (!kReturns && call.record)
    throw std::invalid_argument("vrlis: a gather call with a record needs a visitor that returns its contribution");
  const bool decide = effort.on && effort.decide;
  const double rate = EffortCallRate(effort);
  const CountedWork& costs = LanesWork();
  double call_sum = 0, loop_work = costs.operations.vrl;  // a call not taken still draws its number
  constexpr int kStackVrls = 256;
  SplitSums stack_split[kReturns ? kStackVrls : 1];
  std::vector<SplitSums> heap_split;
  SplitSums* split = nullptr;  // per VRL, where a record learns how splitting pays
  if (record && decide) {
    if (count > kStackVrls) heap_split.resize(std::size_t(count));
    split = count > kStackVrls ? heap_split.data() : stack_split;
    std::fill(split, split + count, SplitSums{0, 0, 0});
  }
  auto finish = [&] {
    if (!record) return;
    record->calls += 1, record->decided += decide ? 1 : 0, record->vrls += count;
    record->call_rate += rate, record->call_m2 += rate * call_sum * call_sum;
    record->work += loop_work;
    for (int i = 0; split && i < count; ++i)
      if (split[i].samples > 1) {
        const double k = split[i].samples, mean = split[i].sum / k;
        record->split_within += std::max(0.0, (split[i].sum_sq - k * mean * mean) / (k - 1));
        record->split_second += split[i].sum_sq / k;
      }
  };
  if (rate < 1 && !CallTakenAt(rate, double(uniform()))) return finish();  // each sample of a taken call weighs 1 / rate more
  // What the record learns from one sample, contribution y to the pixel, effort weight w.
  auto learn = [&](int i, const GatherSample<Real>& s, double w, double y) {
    record->samples += 1, record->sum += y, record->sum_sq += y * y, call_sum += y;
    if (!decide && !(s.over_equiangular > 0 || s.over_mixture > 0)) return;  // nothing else to learn from it
    const double bare = y / w, m2 = w * bare * bare;
    if (decide) record->measured += m2, (w > 1 ? record->roulette_excess : record->split_excess) += m2 * (w - 1);
    if (s.over_equiangular > 0) record->cheapest_excess += y * y * (double(s.over_equiangular) - 1);
    if (s.over_mixture > 0) record->mixture_excess += y * y * (double(s.over_mixture) - 1);
    if (split) split[i].samples += 1, split[i].sum += bare, split[i].sum_sq += bare * bare;
  };
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
    int visits = 0;  // a sample that does not contribute needs no ray: its visit is not counted
    for (int k = 0; k < batch.count; ++k) {
      visits += samples[k].contributes();
      if constexpr (kReturns) {
        const double y = double(visit(batch.source[k], samples[k], batch.effort_weight[k]));
        if (record) learn(batch.source[k], samples[k], double(batch.effort_weight[k]), y);
      } else {
        visit(batch.source[k], samples[k], batch.effort_weight[k]);
      }
    }
    if (record) {
      const int m = static_cast<int>(model);
      record->model_samples[m] += batch.count;
      // The rule's samples that also measured the mixture cost more than the rule alone.
      const bool measured = model == EffortModel::Chosen && effort.measure_mixture;
      if (measured) record->mixture_measured += batch.count;
      else record->model_work[m] += work;
      const double sampled = work + visits * call.visit_work;
      record->sample_work += sampled, record->work += sampled;
    }
    batch.count = 0;
  };
  Real quick[kBoundBatch], tight[kBoundBatch];
  bool tight_taken = false;  // for the block of VRL i
  EffortModel model = EffortModel::Chosen;  // the call's, unless decided per gather
  if constexpr (kPolicy) model = ChooseEffortModel(effort, 1);
  loop_work += count * (costs.operations.vrl + bound_work.before);
  for (int i = 0; i < count; ++i) {
    const bool usable = valid && Validate(vrls[i]) == QueryError::None;
    const int lane = i % kBoundBatch, first = i - lane, block = std::min(kBoundBatch, count - first);
    if (decide && lane == 0) {
      bounds(first, block, quick, nullptr), tight_taken = false;
      loop_work += block * (bound_work.quick + costs.operations.decision);
    }
    int n = 1;
    Real weight = 1;
    if (decide) {
      const double weight_i = call.weights ? double(call.weights[i]) : 1;  // null: all equal
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
      if (record && n > 0) record->predicted += n * predicted() / q;
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
  finish();
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

// Whether GatherMediumVrls with these samplers and call reads its VRLs and the call's weights,
// u the first number its uniform() will return (a renderer draws it from a copy of the
// stream): a call the effort control does not take draws that number, records itself and
// reads neither (VrlMarginal's scores, taken before the decision, read them either way). A
// renderer that builds them per call need not for a call that does not read them, and still
// makes the call; in room, whose calls are taken at about 1%, building them took a fifth of
// a pass. SurfaceGatherReadsVrls: the same for GatherSurfaceVrls.
template <typename Real>
bool MediumGatherReadsVrls(const GatherSamplers& samplers, const EffortCall<Real>& call, double u) {
  return detail::ScoresVrls(samplers.vrl == VrlSamplers::Of<VrlMarginalEntry>(), call) ||
         detail::CallTakenAt(EffortCallRate(call.settings), u);
}
template <typename Real>
bool SurfaceGatherReadsVrls(const EffortCall<Real>& call, double u) {
  return detail::CallTakenAt(EffortCallRate(call.settings), u);
}

// The medium-to-medium gathers of vrls[0, count) against the camera segment:
// visit(i, sample, effort_weight) for every sample taken (an invalid query takes none),
// controlled by `effort` (effort/call.hpp; by default the control is off and nothing learns).
// `samplers`: GatherSamplers (chosen at run time, every pair compiled) or FixedSamplers (one).
template <typename Samplers, typename Real, typename Uniform, typename Visit>
void GatherMediumVrls(Samplers samplers, const RaySegment<Real>& camera, const Medium<Real>& medium,
                      const VrlSegment<Real>* vrls, int count, Uniform&& uniform, Visit&& visit,
                      const EffortCall<typename detail::NonDeduced<Real>::type>& effort = {}) {
  const bool valid = Validate(camera) == QueryError::None && Validate(medium) == QueryError::None;
  const EffortSettings& settings = effort.settings;
  const GatherSamplers named = samplers;
  const CountedWork& costs = LanesWork();
  WithGatherSamplers<Real>(samplers, [&](auto step_one, auto step_two) {
    using VrlSampler = typename decltype(step_one)::type;
    using StepTwo = typename decltype(step_two)::type;
    constexpr bool policy = std::is_same_v<StepTwo, AutoEntry::Sampler<Real>>;
    // VrlMarginal's fits for the gathers whose score reaches the threshold (not auto's
    // accurate model, which is already given by demand).
    constexpr bool marginal = std::is_same_v<VrlSampler, VrlMarginalEntry::Sampler<Real>>;
    const bool chosen = marginal && valid && settings.marginal_threshold > 0;
    const bool scored = valid && detail::ScoresVrls(marginal, effort);
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
      detail::WithWidestLanes([&] { MarginalFitScores(camera, medium, vrls, effort.weights, count, bound, score); });
      for (int i = 0; effort.scores && i < count; ++i) effort.scores->Add(score[i]);
    }
    detail::GatherEachVrl<2, policy>(
        effort, vrls, count, valid, uniform,
        // The tight bounds taken with the scores, counted before the loop.
        scored ? detail::BoundWork{costs.operations.medium_quick_bound, 0, costs.operations.medium_tight_bound}
               : detail::BoundWork{costs.operations.medium_quick_bound, costs.operations.medium_tight_bound},
        [&](int first, int n, Real* quick, Real* tight) {
          if (scored && tight) {  // taken with the scores
            std::copy(bound + first, bound + first + n, tight);
            tight = nullptr;
          }
          if (quick || tight) MediumGatherBounds(camera, vrls + first, n, medium, quick, tight);
        },
        [&](EffortModel model, const auto& b, GatherSample<Real>* samples) {
          const SegmentChoice taken = SegmentSamplerFor(named.segment, model);
          // Its counted work: each sample's, VrlMarginal's fit where it takes one.
          auto with = [&](auto one, auto two, const bool* fitted = nullptr) {
            using One = typename decltype(one)::type;
            SampleMediumGathers<One, typename decltype(two)::type>(ValidQuery{}, camera, medium, b.segments, b.count,
                                                                  b.u[0], b.u[1], samples, settings.measure_mixture,
                                                                  true, fitted);
            int fits = 0;
            if constexpr (std::is_same_v<One, VrlMarginalEntry::Sampler<Real>>)
              for (int k = 0; k < b.count; ++k) fits += !fitted || fitted[k];
            return b.count * (costs.MediumSample(taken) +
                              (settings.measure_mixture ? costs.operations.mixture_density : 0)) +
                   fits * costs.operations.marginal_fit;
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
          for (int k = 0; chosen && k < b.count; ++k) fitted[k] = score[b.source[k]] >= settings.marginal_threshold;
          return with(Type<VrlSampler>{}, Type<StepTwo>{}, chosen ? fitted : nullptr);
        },
        visit);
  });
}

// The medium-to-surface gathers of vrls[0, count) at the point (normal facing the viewer),
// the VRL points by `samplers`' camera sampler (SegmentChoice, GatherSamplers or
// FixedSamplers), as GatherMediumVrls.
template <typename Samplers, typename Real, typename Uniform, typename Visit>
void GatherSurfaceVrls(Samplers samplers, Vec3<Real> point, Vec3<Real> normal, const Medium<Real>& medium,
                       const VrlSegment<Real>* vrls, int count, Uniform&& uniform, Visit&& visit,
                       const EffortCall<typename detail::NonDeduced<Real>::type>& effort = {}) {
  const bool measure_mixture = effort.settings.measure_mixture;
  const bool valid = ValidateSurfacePoint(point, normal) == QueryError::None && Validate(medium) == QueryError::None;
  const SegmentChoice sampler = detail::CameraSamplerOf(samplers);
  const CountedWork& costs = LanesWork();
  detail::WithCameraSampler(samplers, [&](auto entry) {
    using Chosen = typename decltype(entry)::template Sampler<Real>;
    constexpr bool policy = std::is_same_v<Chosen, AutoEntry::Sampler<Real>>;
    detail::GatherEachVrl<1, policy>(
        effort, vrls, count, valid, uniform,
        detail::BoundWork{costs.operations.surface_quick_bound, costs.operations.surface_tight_bound},
        [&](int first, int n, Real* quick, Real* tight) {
          SurfaceGatherBounds(point, normal, vrls + first, n, medium, quick, tight);
        },
        [&](EffortModel model, const auto& b, GatherSample<Real>* samples) {
          const SegmentChoice taken = SegmentSamplerFor(sampler, model);
          auto with = [&](auto type) {
            SampleSurfaceGathers<typename decltype(type)::type>(ValidQuery{}, point, normal, medium, b.segments,
                                                                b.count, b.u[0], samples, measure_mixture);
            return b.count * (costs.SurfaceSample(taken) + (measure_mixture ? costs.operations.mixture_density : 0));
          };
          if constexpr (policy) {
            if (model != EffortModel::Chosen)
              return SegmentSamplers::WithEntry(taken, [&](auto entry) {
                return with(Type<typename decltype(entry)::template Sampler<Real>>{});
              });
          }
          return with(Type<Chosen>{});
        },
        visit);
  });
}

}  // namespace vrlis
