#pragma once
// The medium-to-medium VRL gather (docs/maths.md#estimators, Novák et al. 2012): a point on
// the VRL by step one, then a point on the camera segment by step two, both chosen at run
// time (method.hpp). The integrand, per unit length on both segments, is
//   sigma_s^2 rho(w_c . w) rho(-w_l . w) T(t - tmin) T(v) T(|y - x|) / |y - x|^2,
// w the unit vector from the camera point x(t) to the VRL point y(v).
#include <algorithm>
#include <limits>
#include <optional>
#include <type_traits>

#include "../core/dispatch.hpp"
#include "../method.hpp"
#include "gather_sample.hpp"

namespace vrlis {

// The camera step's query for the VRL point y: the camera segment seen from y.
template <typename Real>
SegmentQuery<Real> CameraStepQuery(const MediumGatherQuery<Real>& q, Vec3<Real> y) {
  return MediumToMediumQuery(q.camera.origin, q.camera.dir, q.camera.tmin, q.camera.tmax, y, q.vrl.dir, q.medium.g,
                             q.medium.sigma_t);
}

// The integrand at (t, v) without visibility, factored by the medium's coefficients. Both
// phase lobes share one square root and one division (their numerators are the medium's).
// kLanes: branch-free, for a loop over a batch's gathers (lane_math.hpp).
template <bool kLanes = false, typename Real>
IntegrandFactors<Real> MediumGatherFactors(const MediumGatherQuery<Real>& q, Real t, Real v) {
  Vec3<Real> x = q.camera.at(t), y = q.vrl.at(v), w = y - x;
  Real r2 = Dot(w, w);
  const bool apart = r2 > 0;
  if (!kLanes && !apart) return {};
  const Real g = q.medium.g;
  Real r = PickSqrt<kLanes>(r2), inv_r = 1 / r;
  Real cos_camera = PickClamp<kLanes>(Dot(q.camera.dir, w) * inv_r, Real(-1), Real(1));
  Real cos_vrl = PickClamp<kLanes>(-Dot(q.vrl.dir, w) * inv_r, Real(-1), Real(1));
  Real d = HenyeyGreensteinBase<kLanes>(g, 1 - cos_camera, 1 + cos_camera) *
           HenyeyGreensteinBase<kLanes>(g, 1 - cos_vrl, 1 + cos_vrl);
  Real lobe_numerator = (1 - g) * (1 + g) * (kInvPi<Real> / 4);
  Real bare = Sqr(lobe_numerator) / (d * PickSqrt<kLanes>(d)) * inv_r * inv_r;
  // (In lanes the coincident points' NaNs are computed, then replaced.)
  return {Pick<kLanes>(apart, bare, Real(0)), Pick<kLanes>(apart, (t - q.camera.tmin) + v + r, Real(0)),
          Pick<kLanes>(apart, r, Real(0)), apart ? 2 : 0};
}

// The integrand's value, and its connection transmittance if asked.
template <typename Real>
Real MediumGatherIntegrand(const MediumGatherQuery<Real>& q, Real t, Real v, Real* transmittance = nullptr) {
  return MediumGatherFactors(q, t, v).value(q.medium, transmittance);
}

// Calls f(Type<StepOneSampler>{}, Type<CameraSampler>{}) for the samplers of `method`:
// a renderer branches on the method once, outside its loop over VRLs.
template <typename Real, typename F>
decltype(auto) WithGatherSamplers(GatherSamplers method, F&& f) {
  return VrlSamplers::WithEntry(method.vrl, [&](auto vrl) {
    return SegmentSamplers::WithEntry(method.segment, [&](auto camera) {
      return f(Type<typename decltype(vrl)::template Sampler<Real>>{},
               Type<typename decltype(camera)::template Sampler<Real>>{});
    });
  });
}
template <typename Real, typename Camera, typename Vrl, typename F>
decltype(auto) WithGatherSamplers(FixedSamplers<Camera, Vrl>, F&& f) {
  return f(Type<typename Vrl::template Sampler<Real>>{}, Type<typename Camera::template Sampler<Real>>{});
}

// The gather's outcome s for step one's sample v and step two's sample t, both usable.
// kLanes: branch-free for a loop over a batch's gathers (in place, as detail::Finish).
template <bool kLanes = false, typename Real>
[[gnu::always_inline]] inline void FinishWithCamera(const MediumGatherQuery<Real>& q, SegmentSample<Real> v,
                                                    SegmentSample<Real> t, GatherSample<Real>& s) {
  s.camera_point = q.camera.at(t.t);
  s.light_point = q.vrl.at(v.t);
  s.t = t.t;
  s.pdf_t = t.pdf;
  s.v = v.t;
  s.pdf_v = v.pdf;
  detail::Finish<kLanes>(s, MediumGatherFactors<kLanes>(q, t.t, v.t), q.medium, t.pdf * v.pdf);
}

// Step two and the weight for step one's sample v (usable or not) and u_camera.
template <typename CameraSampler, typename Real>
[[gnu::always_inline]] inline GatherSample<Real> FinishMediumGather(ValidQuery, const MediumGatherQuery<Real>& q,
                                                                    SegmentSample<Real> v, Real u_camera) {
  if (!detail::Usable(v)) return {};
  const SegmentSample<Real> t = CameraSampler(ValidQuery{}, CameraStepQuery(q, q.vrl.at(v.t))).sample_pdf(u_camera);
  GatherSample<Real> s;
  if (detail::Usable(t)) FinishWithCamera(q, v, t, s);
  return s;
}

// One estimate from two uniform numbers (u_vrl for step one, u_camera for step two) with
// both samplers fixed at compile time, for a query the caller has validated
// (Validate(q) == QueryError::None). Flattened: compilers stop inlining the samplers once a
// translation unit holds many of them (every method of the registry), and the calls then
// cost as much as the arithmetic.
template <typename StepOneSampler, typename CameraSampler, typename Real>
[[gnu::flatten]] GatherSample<Real> SampleMediumGather(ValidQuery, const MediumGatherQuery<Real>& q, Real u_vrl, Real u_camera) {
  return FinishMediumGather<CameraSampler>(ValidQuery{}, q, StepOneSampler(ValidQuery{}, q).sample_pdf(u_vrl), u_camera);
}

namespace detail {
// Camera samplers whose distribution fits a whole batch in lanes: D::SampleLanes over a
// D::TargetLanes, which the medium gathers' queries build.
template <typename S, typename = void>
struct FitsInLanes : std::false_type {};
template <typename D>
struct FitsInLanes<SegmentSampler<D>, std::void_t<typename D::template TargetLanes<1>>> : std::true_type {
  using Fit = D;
};
}  // namespace detail

// Many VRLs against one camera segment, a renderer's inner loop: out[i] is SampleMediumGather
// for the query {camera, vrls[i], medium} with u_vrl[i] and u_camera[i] (each query valid), in
// chunks of up to kGatherChunk gathers. Step one is the same numbers as one at a time, to
// rounding: VrlPoint's runs in vector lanes (SampleVrlPoints), any other by the sampler's
// SampleLanes (VrlMarginal: one fit, its nodes in lanes, for each run of equal VRLs, a split
// gather's samples; the VRL points in lanes). The camera steps run in phases, each a loop:
// their angle domains (all against the one camera segment), their fits and offsets, then their
// points and the integrands. The first and the last run in vector lanes too, to rounding the
// one-at-a-time numbers (lane_math.hpp); so do the fits of every sampler whose distribution
// has a form in lanes (FitsInLanes: Novák's and FullProduct's, their closed-form inversions
// one gather at a time; the Cauchy samplers' fits and inversions, their sines one gather at a
// time; `auto`'s rule in lanes (AutoAngle::ChooseLanes), then each
// model's fits in lanes of their own), the others' one gather at a time. One
// gather is a long chain of dependent operations and one vector of lanes is still one chain;
// the gathers of a phase are independent, and several vectors of them let the processor
// overlap their chains (lanes over 8 gathers at a time gained 10%, over 32 a factor 2 for
// equiangular sampling: GatherBatch/ in bench/bench_gather.cpp). With `auto` as the camera
// sampler and measure_mixture, each sample also carries GatherSample::over_mixture (a
// CauchyMixture fit per sample).
namespace detail {
template <typename StepOneSampler, typename CameraSampler, typename Real>
[[gnu::flatten]] void SampleMediumGathersAsBuilt(const RaySegment<Real>& camera, const Medium<Real>& medium,
                                                 const VrlSegment<Real>* vrls, int count, const Real* u_vrl,
                                                 const Real* u_camera, GatherSample<Real>* out,
                                                 bool measure_mixture, const bool* fitted) {
  constexpr int kSize = kGatherChunk;
  for (int first = 0; first < count; first += kSize) {
    const int n = std::min(kSize, count - first);
    const int lanes = WholeLanes(n);
    SegmentSample<Real> v[kSize];
    if constexpr (std::is_same_v<StepOneSampler, VrlPoint<Real>>) {
      SampleVrlPoints<kSize>(ValidQuery{}, camera, vrls + first, n, u_vrl + first, v);
    } else {
      StepOneSampler::template SampleLanes<kSize>(ValidQuery{}, camera, medium, vrls + first, n, u_vrl + first, v,
                                                  fitted ? fitted + first : nullptr);
    }
    // The lanes' inputs (the unused lanes repeat the first gather).
    const VrlLanes<Real, kSize> vrl(vrls + first, n);
    Real vt[kSize], vpdf[kSize];
    for (int i = 0; i < lanes; ++i) vt[i] = v[i < n ? i : 0].t, vpdf[i] = v[i < n ? i : 0].pdf;
    AngleFrameLanes<Real, kSize> frames;
    const Vec3<Real> origin = camera.origin, dir = camera.dir;  // (copies of the whole
    const Real tmin = camera.tmin, tmax = camera.tmax;           // vectors in the loop keep it scalar)
    for (int i = 0; i < lanes; ++i) frames.set(i, ReduceToAngles<true>(vrl[i].at(vt[i]), origin, dir, tmin, tmax));
    constexpr bool kAuto = std::is_same_v<CameraSampler, AutoEntry::Sampler<Real>>;
    // One-at-a-time fits, none where step one sampled nothing (a sampler fitted in lanes
    // needs none; their frame kept GCC from inlining the lanes' finish).
    std::optional<CameraSampler> fit[FitsInLanes<CameraSampler>::value || kAuto ? 1 : kSize];
    auto step_query = [&](int i) {
      MediumGatherQuery<Real> q{camera, vrls[first + i], medium};
      return CameraStepQuery(q, q.vrl.at(v[i].t));
    };
    Real delta[kSize] = {}, pdf_delta[kSize] = {};  // pdf 0: nothing sampled
    Real u[kSize];
    for (int i = 0; i < lanes; ++i) u[i] = u_camera[first + (i < n ? i : 0)];
    // The lanes' samples, except where SegmentSampler samples nothing (sample_offset).
    auto take = [&](const SegmentSample<Real>* d) {
      const bool representable = RepresentableLength(camera.tmax - camera.tmin);
      for (int i = 0; i < n; ++i)
        if (detail::Usable(v[i]) && frames.width[i] >= std::numeric_limits<Real>::min() && representable)
          delta[i] = d[i].t, pdf_delta[i] = d[i].pdf;
    };
    if constexpr (FitsInLanes<CameraSampler>::value) {
      using Fit = typename FitsInLanes<CameraSampler>::Fit;
      typename Fit::template TargetLanes<kSize> targets;
      targets.template build<Accuracy::Fit>(frames, vrl.dx, vrl.dy, vrl.dz, camera.dir, medium.g, medium.sigma_t, lanes);
      SegmentSample<Real> d[kSize];
      Fit::template SampleLanes<kSize>(targets, u, lanes, d);
      take(d);
    } else if constexpr (kAuto) {
      AutoModel models[kSize];
      const bool bounded = std::isfinite(tmax);
      Real depth[kSize];
      if (bounded)
        for (int i = 0; i < lanes; ++i) depth[i] = DepthGrowth<true>(vrl[i].at(vt[i]), origin, dir, tmin, tmax);
      AutoAngle<Real>::template ChooseLanes<kSize>(frames, vrl.dx, vrl.dy, vrl.dz, dir, medium.g, medium.sigma_t,
                                                   bounded ? depth : nullptr, lanes, models);
      for (int i = 0; i < lanes; ++i) {  // (nothing sampled: the cheapest)
        const bool usable = detail::Usable(SegmentSample<Real>{vt[i], vpdf[i]}), sampled = (i < n) & usable;
        models[i] = sampled ? models[i] : AutoModel::Equiangular;
      }
      SegmentSample<Real> d[kSize];
      AutoAngle<Real>::template SampleLanes<kSize>(models, frames, vrl.dx, vrl.dy, vrl.dz, camera.dir, medium.g,
                                                   medium.sigma_t, u, lanes, d);
      take(d);
    } else {
      for (int i = 0; i < n; ++i)
        if (detail::Usable(v[i])) {
          const SegmentQuery<Real> q = step_query(i);
          fit[i].emplace(ValidQuery{}, q, AngleDomain<Real>(q, frames[i]));
        }
      for (int i = 0; i < n; ++i)
        if (fit[i]) {
          SegmentSample<Real> d = fit[i]->sample_offset(u_camera[first + i]);
          delta[i] = d.t, pdf_delta[i] = d.pdf;
        }
    }
    GatherSample<Real> samples[kSize];
    bool usable[kSize];
    for (int i = 0; i < lanes; ++i) {
      AnglePoint<Real> p = PointAtOffset<true>(frames[i], camera.tmin, camera.tmax, delta[i]);
      SegmentSample<Real> t{p.t, pdf_delta[i] * p.dtheta_dt}, vs{vt[i], vpdf[i]};
      const bool v_usable = Usable(vs), t_usable = Usable(t);
      usable[i] = v_usable & t_usable;  // (not &&: a branch keeps the loop scalar)
      FinishWithCamera<true>(MediumGatherQuery<Real>{camera, vrl[i], medium}, vs, t, samples[i]);
    }
    // `auto`'s samples over equiangular sampling's density: the two share the angle's
    // Jacobian, so the ratio is the angle's density times the interval's width.
    Real over_equiangular[kSize];
    if constexpr (kAuto)
      for (int i = 0; i < lanes; ++i) over_equiangular[i] = FiniteOrZero<true>(pdf_delta[i] * frames.width[i]);
    for (int i = 0; i < n; ++i) {
      GatherSample<Real>& g = out[first + i];
      g = usable[i] ? samples[i] : GatherSample<Real>{};
      if constexpr (kAuto) {
        if (!g.contributes()) continue;
        g.over_equiangular = over_equiangular[i];
        if (measure_mixture) {
          const SegmentQuery<Real> q = step_query(i);
          g.over_mixture = detail::OverDensity<CauchyMixtureAngle<Real>>(AngleDomain<Real>(q, frames[i]), q,
                                                                         SegmentSample<Real>{g.t, g.pdf_t});
        }
      }
    }
  }
}
}  // namespace detail

// The batch above, on the widest vector lanes the processor has (core/dispatch.hpp);
// `widest` false: as built. fitted, if set, says which gathers' step one VrlMarginal fits
// (VrlMarginal::SampleLanes; the others take VrlPoint's density); other step ones ignore it.
template <typename StepOneSampler, typename CameraSampler, typename Real>
void SampleMediumGathers(ValidQuery, const RaySegment<Real>& camera, const Medium<Real>& medium,
                         const VrlSegment<Real>* vrls, int count, const Real* u_vrl, const Real* u_camera,
                         GatherSample<Real>* out, bool measure_mixture = false, bool widest = true,
                         const bool* fitted = nullptr) {
  detail::WithWidestLanes(
      [&] {
        detail::SampleMediumGathersAsBuilt<StepOneSampler, CameraSampler>(camera, medium, vrls, count, u_vrl,
                                                                          u_camera, out, measure_mixture, fitted);
      },
      widest);
}

// The same with the samplers chosen at run time; any query (an invalid one samples nothing).
template <typename Real>
GatherSample<Real> SampleMediumGather(GatherSamplers method, const MediumGatherQuery<Real>& q, Real u_vrl,
                                      Real u_camera) {
  if (Validate(q) != QueryError::None) return {};
  return WithGatherSamplers<Real>(method, [&](auto step_one, auto step_two) {
    return SampleMediumGather<typename decltype(step_one)::type, typename decltype(step_two)::type>(ValidQuery{}, q,
                                                                                                  u_vrl, u_camera);
  });
}

}  // namespace vrlis
