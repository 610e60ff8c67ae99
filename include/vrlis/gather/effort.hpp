#pragma once
// How often to take one VRL gather (docs/maths.md#effort; Rath et al. 2022, "EARS:
// Efficiency-Aware Russian Roulette and Splitting"): q = sqrt(price x predicted second
// moment), clamped to [floor, ceiling], taken floor(q + u) times with weight 1 / q each:
// Russian roulette below one, splitting above, unbiased for any q > 0 (and q is never 0).
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "../core/gather_query.hpp"
#include "../core/phase.hpp"

namespace vrlis {

// The effort control's parameters. `price` is what one unit of a gather's second moment is
// worth in gathers: (image cost / image variance) / (cost of one gather), learned by the
// renderer from earlier passes only (a decision that saw the current pass would bias it).
// With `on` false, or no price learned yet (price not positive and finite), every gather is
// taken once with weight 1, exactly as without the control.
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
  // of the same pixel tile): sqrt((its second moment / the seconds its decisions take) x
  // (image cost / image variance)), docs/maths.md#effort-calls. Below one (and priced) the call is taken with that
  // probability, at least `floor` (one number drawn first), and each gather in a taken call
  // 1 / rate times as often: every gather's expected samples and weights stay those of its
  // own demand, and the calls not taken save their bounds. 1, more or NaN: every call taken.
  double call_demand = 1;
};

// What the renderer needs to calibrate its predictions from a pass: the predicted second
// moments (w x bound)^2, summed over the samples taken with their effort weights 1 / q (an
// unbiased estimate of their sum over the gathers considered, as the renderer's own sum
// over the samples is of the true second moments). Its own sum of the samples'
// (effort weight x contribution^2), visibility included, estimates the true one: their ratio,
// learned from earlier passes, scales the price (a bound is not a second moment).
// `sample_seconds` is the time spent sampling and connecting the samples: the rest of a call's
// time is its decisions' (docs/maths.md#effort-calls).
struct EffortTally {
  double predicted = 0;
  double sample_seconds = 0;
};

// Whether the control has a price to decide by: on, and a positive finite price learned.
inline bool EffortPriced(const EffortSettings& e) { return e.on && e.price > 0 && std::isfinite(e.price); }

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
// the model-blind prediction many times).
enum class EffortModel { Chosen, Accurate };
inline EffortModel ChooseEffortModel(const EffortSettings& e, double demand) {
  if (!EffortPriced(e)) return EffortModel::Chosen;
  return SplitDemand(e, demand) >= e.accurate * e.ceiling ? EffortModel::Accurate : EffortModel::Chosen;
}

// floor(q + u) for u uniform in [0, 1): q samples on average, stochastically rounded.
inline int EffortSamples(double q, double u) { return static_cast<int>(std::floor(q + u)); }

namespace detail {
// The Henyey-Greenstein lobe's largest value over all angles, at cos = sign(g).
template <typename Real>
Real PhaseMax(Real g) {
  return HenyeyGreenstein(std::abs(g), Real(1));
}
// The range [lo, hi] of a . (p(s) - o) / |p(s) - o| over p(s) = p0 + s b, s in [s0, s1]
// (|a| = |b| = 1; s1 may be infinite, where the cosine tends to a . b). Along a line the
// cosine has at most one interior extremum, at s* = (alpha delta - beta gamma) / (beta delta
// - alpha) with alpha = a . P, beta = a . b, gamma = P . P, delta = P . b, P = p0 - o.
template <typename Real>
std::pair<Real, Real> CosineRange(Vec3<Real> a, Vec3<Real> o, Vec3<Real> p0, Vec3<Real> b, Real s0, Real s1) {
  const Vec3<Real> P = p0 - o;
  const Real alpha = Dot(a, P), beta = Dot(a, b), gamma = Dot(P, P), delta = Dot(P, b);
  auto at = [&](Real s) {
    Real len2 = gamma + 2 * delta * s + s * s;
    return len2 > 0 ? (alpha + beta * s) / std::sqrt(len2) : beta;
  };
  Real lo = at(s0), hi = lo;
  auto add = [&](Real c) { lo = std::min(lo, c), hi = std::max(hi, c); };
  add(std::isfinite(s1) ? at(s1) : beta);
  Real den = beta * delta - alpha, s = (alpha * delta - beta * gamma) / den;
  if (den != 0 && s > s0 && s < s1) add(at(s));
  return {std::max(lo, Real(-1)), std::min(hi, Real(1))};
}
// The largest value of a Henyey-Greenstein lobe whose cosine lies in [lo, hi]: it is
// monotone in the cosine, largest at hi for g > 0 and at lo for g < 0.
template <typename Real>
Real PhaseMax(Real g, std::pair<Real, Real> range) {
  return HenyeyGreenstein(g, g < 0 ? range.first : range.second);
}
// Int_0^len dv / h(v) with h(v)^2 = r^2 + s^2 (v - v0)^2: the distance from y(v) to a line at
// closest distance r, crossing at angle asin(s) where the VRL is at v0.
// (In double: near-parallel lines put v0 far away, and the two terms nearly cancel.)
template <typename Real>
Real InverseDistanceIntegral(Real r, Real s, Real v0, Real len) {
  if (s < Real(1e-4)) return len / r;
  double a = double(s) / r;
  return Real((std::asinh(a * (double(len) - v0)) + std::asinh(a * v0)) / s);
}
}  // namespace detail

// The camera segment's and the VRL's lines: their distance r, the sine s of the angle
// between them and the VRL's parameter v0 where it comes closest to the camera line.
template <typename Real>
struct ClosestApproach {
  Real r = 0, s = 0, v0 = 0;
};

template <typename Real>
ClosestApproach<Real> Closest(const RaySegment<Real>& camera, const VrlSegment<Real>& vrl) {
  Vec3<Real> n = Cross(camera.dir, vrl.dir), w0 = vrl.origin - camera.origin;
  ClosestApproach<Real> c;
  c.s = Length(n);
  Real b = Dot(camera.dir, vrl.dir);
  bool parallel = c.s < Real(1e-4);
  c.v0 = parallel ? vrl.length / 2 : (b * Dot(camera.dir, w0) - Dot(vrl.dir, w0)) / (c.s * c.s);
  c.r = std::max(parallel ? Length(Cross(w0, camera.dir)) : std::abs(Dot(w0, n)) / c.s, Real(1e-6));
  return c;
}

// A bound of Int Int du dv / |w|^2 over both segments: the smaller of 1 / r^2 over both
// lengths and pi / h(v) integrated along the VRL (h(v) the distance from y(v) to the camera line).
template <typename Real>
Real InverseSquareBound(const RaySegment<Real>& camera, const VrlSegment<Real>& vrl, const ClosestApproach<Real>& c) {
  return std::min((camera.tmax - camera.tmin) * vrl.length / (c.r * c.r),
                  kPi<Real> * detail::InverseDistanceIntegral(c.r, c.s, c.v0, vrl.length));
}

// A bound of the medium-to-medium gather's mean, Int Int f du dv over both segments (the
// integrand of medium_gather.hpp): 1 / |w|^2 by InverseSquareBound, each phase by its largest
// value over the cosines the two segments allow, and the three legs' transmittance by its value
// at (tmin, 0): the optical length (t - tmin) + v + |x(t) - y(v)| grows with t and with v (a
// distance changes no faster than its end point). The camera phase's cosine d . w / |w|
// (w = y - x) falls as t grows, so it is largest at tmin and smallest at tmax, and the VRL's
// -e . w / |w| falls as v grows: each range is one CosineRange along the other segment.
// Cheap: no sampler.
template <typename Real>
Real MediumGatherBound(const RaySegment<Real>& camera, const VrlSegment<Real>& vrl, const Medium<Real>& m) {
  ClosestApproach<Real> c = Closest(camera, vrl);
  const Vec3<Real> x0 = camera.at(camera.tmin), y0 = vrl.origin, y1 = vrl.at(vrl.length);
  auto camera_hi = detail::CosineRange(camera.dir, x0, y0, vrl.dir, Real(0), vrl.length);
  std::pair<Real, Real> camera_cos{Real(-1), camera_hi.second};
  if (std::isfinite(camera.tmax))
    camera_cos.first = detail::CosineRange(camera.dir, camera.at(camera.tmax), y0, vrl.dir, Real(0), vrl.length).first;
  const std::pair<Real, Real> vrl_cos{
      detail::CosineRange(vrl.dir, y1, x0, camera.dir, Real(0), camera.tmax - camera.tmin).first,
      detail::CosineRange(vrl.dir, y0, x0, camera.dir, Real(0), camera.tmax - camera.tmin).second};
  Real phases = detail::PhaseMax(m.g, camera_cos) * detail::PhaseMax(m.g, vrl_cos);
  return Sqr(m.sigma_s) * phases * std::exp(-m.sigma_t * Length(y0 - x0)) * InverseSquareBound(camera, vrl, c);
}

// MediumGatherBound with both phases by their largest value over all angles and 1 / |w|^2 by
// 1 / r^2 over both lengths or pi / r along the VRL (h(v) >= r): looser, and no inverse
// hyperbolic sine.
template <typename Real>
Real MediumGatherQuickBound(const RaySegment<Real>& camera, const VrlSegment<Real>& vrl, const Medium<Real>& m) {
  Real nearest = Length(vrl.origin - camera.at(camera.tmin)), r = Closest(camera, vrl).r;
  return Sqr(m.sigma_s * detail::PhaseMax(m.g)) * std::exp(-m.sigma_t * nearest) * vrl.length *
         std::min((camera.tmax - camera.tmin) / (r * r), kPi<Real> / r);
}

// A bound of the medium-to-surface gather's mean, Int f dv (surface_gather.hpp, without the
// albedo): zero when the whole VRL is behind the surface (then so is the gather; it is still
// taken at the floor's rate), else the phase by its value at the largest cosine -e . w / |w|
// allows (it falls as v grows: the ends give its range), the cosine n . w / |w| by its largest
// value along the VRL, the two legs' transmittance by its value at the VRL's origin
// (v + |y(v) - x| grows with v), times Int dv / |w|^2 itself: |w|^2 = h^2 + (v - v0)^2 (h the
// point's distance from the VRL's line, v0 its foot) integrates to a difference of arctangents.
template <typename Real>
Real SurfaceGatherBound(Vec3<Real> point, Vec3<Real> normal, const VrlSegment<Real>& vrl, const Medium<Real>& m) {
  Vec3<Real> w0 = vrl.origin - point, w1 = w0 + vrl.length * vrl.dir;
  if (!(Dot(normal, w0) > 0) && !(Dot(normal, w1) > 0)) return 0;
  Real h = std::max(Length(Cross(w0, vrl.dir)), Real(1e-6)), v0 = -Dot(vrl.dir, w0);
  Real l0 = Length(w0), l1 = Length(w1);
  std::pair<Real, Real> phase_cos{l1 > 0 ? -Dot(vrl.dir, w1) / l1 : Real(-1), l0 > 0 ? -Dot(vrl.dir, w0) / l0 : Real(1)};
  Real cosine = detail::CosineRange(normal, point, vrl.origin, vrl.dir, Real(0), vrl.length).second;
  Real inverse_square = (std::atan((vrl.length - v0) / h) + std::atan(v0 / h)) / h;
  return m.sigma_s * detail::PhaseMax(m.g, phase_cos) * std::max(cosine, Real(0)) * kInvPi<Real> *
         std::exp(-m.sigma_t * l0) * inverse_square;
}

// SurfaceGatherBound with the phase by its largest value over all angles, the cosine by one
// and Int dv / |w|^2 by min(length / h^2, pi / h): looser, and no arctangent.
template <typename Real>
Real SurfaceGatherQuickBound(Vec3<Real> point, Vec3<Real> normal, const VrlSegment<Real>& vrl, const Medium<Real>& m) {
  Vec3<Real> w0 = vrl.origin - point;
  if (!(Dot(normal, w0) > 0) && !(Dot(normal, w0 + vrl.length * vrl.dir) > 0)) return 0;
  Real h = std::max(Length(Cross(w0, vrl.dir)), Real(1e-6));
  return m.sigma_s * detail::PhaseMax(m.g) * kInvPi<Real> * std::exp(-m.sigma_t * Length(w0)) *
         std::min(vrl.length / (h * h), kPi<Real> / h);
}

}  // namespace vrlis
