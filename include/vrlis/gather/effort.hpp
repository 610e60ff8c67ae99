#pragma once
// How often to take one VRL gather (docs/maths.md#effort; Rath et al. 2022, "EARS:
// Efficiency-Aware Russian Roulette and Splitting"): q = sqrt(price x predicted second
// moment), clamped to [floor, ceiling], taken floor(q + u) times with weight 1 / q each:
// Russian roulette below one, splitting above, unbiased for any q > 0.
#include <algorithm>
#include <cmath>

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
  double floor = 0.05;   // the largest roulette weight is 1 / floor (EARS's bounds)
  double ceiling = 20;   // at most this many samples of one gather
};

// What the renderer needs to calibrate its predictions from a pass: the sum of the predicted
// second moments (w x bound)^2 of the gathers considered. Its own sum of the samples'
// (effort weight x contribution^2), visibility included, estimates the true one: their ratio,
// learned from earlier passes, scales the price (a bound is not a second moment).
struct EffortTally {
  double predicted = 0;
};

// The expected number of samples of a gather whose second moment is predicted as m2.
// A prediction of zero is a bound of zero (the gather is zero): no sample at all.
inline double EffortQ(const EffortSettings& e, double m2) {
  if (!e.on || !(e.price > 0) || !std::isfinite(e.price)) return 1;
  if (std::isnan(m2)) return 1;
  if (!(m2 > 0)) return 0;
  double q = std::sqrt(e.price * m2);
  return std::isfinite(q) ? std::clamp(q, e.floor, e.ceiling) : e.ceiling;
}

// floor(q + u) for u uniform in [0, 1): q samples on average, stochastically rounded.
inline int EffortSamples(double q, double u) { return static_cast<int>(std::floor(q + u)); }

namespace detail {
template <typename Real>
Real PhaseMax(Real g) {
  return HenyeyGreenstein(std::abs(g), Real(0), Real(2));
}
// Int_0^len dv / h(v) with h(v)^2 = r^2 + s^2 (v - v0)^2: the distance from y(v) to a line at
// closest distance r, crossing at angle asin(s) where the VRL is at v0.
template <typename Real>
Real InverseDistanceIntegral(Real r, Real s, Real v0, Real len) {
  if (s < Real(1e-4)) return len / r;
  return (std::asinh(s * (len - v0) / r) + std::asinh(s * v0 / r)) / s;
}
}  // namespace detail

// A bound of the medium-to-medium gather's mean, Int Int f du dv over both segments (the
// integrand of medium_gather.hpp): both phase values by their maximum, the segments'
// transmittances by one, the connection's by exp(-sigma_t r) and 1 / |w|^2 by the smaller of
// 1 / r^2 over both lengths and pi / h(v) integrated along the VRL, r the distance between
// the two lines. Cheap: no sampler is built.
template <typename Real>
Real MediumGatherBound(const RaySegment<Real>& camera, const VrlSegment<Real>& vrl, const Medium<Real>& m) {
  Vec3<Real> n = Cross(camera.dir, vrl.dir), w0 = vrl.origin - camera.origin;
  Real s = Length(n);
  Real b = Dot(camera.dir, vrl.dir);
  // The VRL's parameter closest to the camera line, and the lines' distance.
  Real v0 = s < Real(1e-4) ? Real(0) : (b * Dot(camera.dir, w0) - Dot(vrl.dir, w0)) / (s * s);
  Real r = s < Real(1e-4) ? Length(Cross(w0, camera.dir)) : std::abs(Dot(w0, n)) / s;
  r = std::max(r, Real(1e-6));
  Real length_c = camera.tmax - camera.tmin;
  Real geometry = std::min(length_c * vrl.length / (r * r),
                           kPi<Real> * detail::InverseDistanceIntegral(r, s, v0, vrl.length));
  return Sqr(m.sigma_s * detail::PhaseMax(m.g)) * std::exp(-m.sigma_t * r) * geometry;
}

// A bound of the medium-to-surface gather's mean, Int f dv (surface_gather.hpp, without
// the albedo): zero when the whole VRL is behind the surface, else the phase by its maximum,
// the cosine and the VRL's transmittance by one, 1 / |w|^2 by min(1 / h^2, ...) integrated,
// h the distance from the point to the VRL's line.
template <typename Real>
Real SurfaceGatherBound(Vec3<Real> point, Vec3<Real> normal, const VrlSegment<Real>& vrl, const Medium<Real>& m) {
  Vec3<Real> w0 = vrl.origin - point;
  if (!(Dot(normal, w0) > 0) && !(Dot(normal, w0 + vrl.length * vrl.dir) > 0)) return 0;
  Real h = std::max(Length(Cross(w0, vrl.dir)), Real(1e-6));
  Real geometry = std::min(vrl.length / (h * h), kPi<Real> / h);
  return m.sigma_s * detail::PhaseMax(m.g) * kInvPi<Real> * std::exp(-m.sigma_t * h) * geometry;
}

}  // namespace vrlis
