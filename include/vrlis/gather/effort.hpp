#pragma once
// How often to take one VRL gather (docs/maths.md#effort; Rath et al. 2022, "EARS:
// Efficiency-Aware Russian Roulette and Splitting"): q = sqrt(price x predicted second
// moment), clamped to [floor, ceiling], taken floor(q + u) times with weight 1 / q each:
// Russian roulette below one, splitting above, unbiased for any q > 0 (and q is never 0).
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

// The expected number of samples of a gather whose second moment is predicted as m2. Never
// zero: a prediction that rounds to zero must not drop a gather that is not (a bias).
inline double EffortQ(const EffortSettings& e, double m2) {
  if (!e.on || !(e.price > 0) || !std::isfinite(e.price) || std::isnan(m2)) return 1;
  double q = std::sqrt(e.price * std::max(m2, 0.0));
  return std::isfinite(q) ? std::clamp(q, e.floor, e.ceiling) : e.ceiling;
}

// floor(q + u) for u uniform in [0, 1): q samples on average, stochastically rounded.
inline int EffortSamples(double q, double u) { return static_cast<int>(std::floor(q + u)); }

namespace detail {
// The Henyey-Greenstein phase function's largest value, at cos = sign(g).
template <typename Real>
Real PhaseMax(Real g) {
  return HenyeyGreenstein(std::abs(g), Real(0), Real(2));
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
// integrand of medium_gather.hpp): both phases by their maximum, the segments' transmittances
// by one, the connection's by exp(-sigma_t r), 1 / |w|^2 by InverseSquareBound. Cheap: no
// sampler. (The phases at the closest points instead, a prediction rather than a bound,
// ranked gathers worse: docs/maths.md#effort.)
template <typename Real>
Real MediumGatherBound(const RaySegment<Real>& camera, const VrlSegment<Real>& vrl, const Medium<Real>& m) {
  ClosestApproach<Real> c = Closest(camera, vrl);
  return Sqr(m.sigma_s * detail::PhaseMax(m.g)) * std::exp(-m.sigma_t * c.r) * InverseSquareBound(camera, vrl, c);
}

// A bound of the medium-to-surface gather's mean, Int f dv (surface_gather.hpp, without the
// albedo): zero when the whole VRL is behind the surface (then so is the gather; it is still
// taken at the floor's rate), else the phase by its maximum, the cosine and the VRL's transmittance by one, the connection's by
// exp(-sigma_t h) and Int dv / |w|^2 by min(length / h^2, pi / h), h the distance from the
// point to the VRL's line.
template <typename Real>
Real SurfaceGatherBound(Vec3<Real> point, Vec3<Real> normal, const VrlSegment<Real>& vrl, const Medium<Real>& m) {
  Vec3<Real> w0 = vrl.origin - point;
  if (!(Dot(normal, w0) > 0) && !(Dot(normal, w0 + vrl.length * vrl.dir) > 0)) return 0;
  Real h = std::max(Length(Cross(w0, vrl.dir)), Real(1e-6));
  return m.sigma_s * detail::PhaseMax(m.g) * kInvPi<Real> * std::exp(-m.sigma_t * h) *
         std::min(vrl.length / (h * h), kPi<Real> / h);
}

}  // namespace vrlis
