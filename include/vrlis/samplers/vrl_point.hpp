#pragma once
// Step one of Novák's estimator: a point on the VRL with density proportional to the
// inverse distance from the VRL point to the camera line (docs/maths.md#step-one),
//   p(v) proportional to 1 / sqrt(1 + x(v)^2),  x(v) = k (v - v0),  k = sin(a) / h.
// The CDF is asinh(x(v)) - asinh(x(tmin)), computed without cancellation.
//
// Contract: error() is Validate(query) (for a gather query, Validate of the whole gather);
// when it is not QueryError::None, valid() is false, sample() and invert() return NaN and
// pdf() returns 0. Parallel lines give the uniform density (the
// limit k -> 0). Intersecting lines (h -> 0) have a non-integrable 1 / |v - v0| target;
// h is floored at the rounding noise of the inputs, so the density is sharply peaked at
// v0 but finite. A VRL shorter than min<Real> / epsilon<Real> (zero length included)
// samples tmin with pdf 0.
#include <limits>
#include <string_view>

#include "../core/math.hpp"
#include "../core/gather_query.hpp"
#include "../core/vec3.hpp"

namespace vrlis {

template <typename Real>
struct VrlPointQuery {
  Vec3<Real> origin{}, dir{};  // the VRL y(v) = origin + v dir, dir unit length
  Real tmin = 0, tmax = 0;     // both finite
  Vec3<Real> line_origin{}, line_dir{};  // the camera line, line_dir unit length
};

// NonFinite (tmax included: the density's tail makes an unbounded VRL unnormalisable),
// NotUnitDirection, ReversedSegment or OutOfRange, as Validate(SegmentQuery).
template <typename Real>
QueryError Validate(const VrlPointQuery<Real>& q) {
  if (!detail::AllFinite(q.origin, q.dir, q.line_origin, q.line_dir, q.tmin, q.tmax)) return QueryError::NonFinite;
  if (!detail::IsUnit(q.dir) || !detail::IsUnit(q.line_dir)) return QueryError::NotUnitDirection;
  if (!(q.tmax >= q.tmin)) return QueryError::ReversedSegment;
  if (!detail::InRange(q.origin) || !detail::InRange(q.line_origin) || std::abs(q.tmin) > MaxCoordinate<Real>() ||
      std::abs(q.tmax) > MaxCoordinate<Real>())
    return QueryError::OutOfRange;
  return QueryError::None;
}

namespace detail {

// Step one's density on one VRL, and the outward walk that samples it: from the point the
// samples reach first, tmin when x >= 0 throughout, tmax when x <= 0, else v0 with the
// masses on either side of it, so that no walk moves towards v0, where digits cancel.
template <typename Real>
struct VrlPointDensity {
  Real tmin = 0, tmax = 0;
  Real k = 0, xa = 0, total = 0;      // x(v) = xa + k (v - tmin); k = 0: uniform
  Real sa = 1, sb = 1;                 // sqrt(1 + x^2) at tmin and at tmax
  Real start = 0, x0 = 0, r0 = 1, before = 0;  // the walk: where it starts, |x| and sqrt(1 + x^2) there, the CDF there
};

// The fit for a valid query of representable length. With kLanes branch-free (every case
// computed, then selected), so that a loop over VRLs vectorises.
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline VrlPointDensity<Real> FitVrlPointDensity(const VrlPointQuery<Real>& q) {
  VrlPointDensity<Real> f;
  f.tmin = q.tmin;
  f.tmax = q.tmax;
  Vec3<Real> d = q.line_origin - q.origin, cross = Cross(q.dir, q.line_dir);
  Real sin2 = Dot(cross, cross), sin_a, inv_sin_a;
  if constexpr (kLanes) {
    inv_sin_a = RsqrtLanes(sin2);
    sin_a = sin2 * inv_sin_a;
  } else {  // (parallel lines: 0, as the lanes' 0 * RsqrtLanes(0), so that nothing below is NaN)
    sin_a = std::sqrt(sin2);
    inv_sin_a = sin_a > 0 ? 1 / sin_a : Real(0);
  }
  // (Picks, not std::max or std::min, here and below: their branches would take the
  // arithmetic that follows into them, and a loop over lanes would stay scalar.)
  Real h = std::abs(Dot(d, cross)) * inv_sin_a,
       floor = NoiseFloor(std::abs(d.x) + std::abs(d.y) + std::abs(d.z) + std::abs(q.tmin) + std::abs(q.tmax));
  h = Pick<kLanes>(h < floor, floor, h);
  Real v0 = (Dot(d, q.dir) - Dot(d, q.line_dir) * Dot(q.dir, q.line_dir)) * Sqr(inv_sin_a);
  Real k = sin_a / h, kl = k * (q.tmax - q.tmin);
  Real xa = k * (q.tmin - v0), xb = xa + kl;
  Real sa = PickSqrt<kLanes>(1 + xa * xa), sb = PickSqrt<kLanes>(1 + xb * xb);
  bool inside = (xa < 0) & (xb > 0), from_tmin = xa >= 0;
  // Inside: the masses of [tmin, v0] and [v0, tmax], asinh(-xa) and asinh(xb); else the whole
  // mass and 0.
  Real a = Log1pLanes(Pick<kLanes>(inside, AsinhArgument(-xa, sa), AsinhDifferenceArgument(xa, kl, sa, sb)));
  Real b = Log1pLanes(Pick<kLanes>(inside, AsinhArgument(xb, sb), Real(0)));
  f.total = a + b;
  f.sa = sa;
  f.sb = sb;
  f.start = Pick<kLanes>(inside, v0, Pick<kLanes>(from_tmin, q.tmin, q.tmax));
  f.x0 = Pick<kLanes>(inside, Real(0), Pick<kLanes>(from_tmin, xa, -xb));
  f.r0 = Pick<kLanes>(inside, Real(1), Pick<kLanes>(from_tmin, sa, sb));
  f.before = Pick<kLanes>(inside, a, Pick<kLanes>(from_tmin, Real(0), f.total));
  f.xa = xa;
  // Else uniform: parallel lines; a density that varies by at most k L / 2 < epsilon over the
  // VRL (the asinh difference of a subnormal k L would have no digits left); no finite mass.
  bool lines_shape = (sin_a > 0) & (kl > std::numeric_limits<Real>::epsilon());
  bool finite_mass = (f.total > 0) & (f.total <= std::numeric_limits<Real>::max());
  bool shaped = lines_shape & finite_mass;
  f.k = Pick<kLanes>(shaped, k, Real(0));
  return f;
}

// A sample and its density, with kLanes branch-free. The walk covers the mass |e| from its start: for
// x0 >= 0 and x1 = sinh(asinh(x0) + |e|), x1 - x0 and sqrt(1 + x1^2) = cosh(...) as sums of
// positive terms. One expm1 gives both hyperbolic functions of |e|: with m = expm1(|e| / 2),
// sinh(|e| / 2) = m (m + 2) / (2 (m + 1)), cosh(|e| / 2) - 1 = m^2 / (2 (m + 1)) and
// sinh(|e|) = 2 sinh(|e| / 2) cosh(|e| / 2).
template <bool kLanes, typename Real>
[[gnu::always_inline]] inline SegmentSample<Real> SampleVrlPointDensity(const VrlPointDensity<Real>& f, Real u) {
  Real e = u * f.total - f.before;  // the mass from the start to the sample, signed by direction
  Real m = Expm1Lanes(std::abs(e) / 2), inv = 1 / (2 * (m + 1));
  Real sh_half = m * (m + 2) * inv, ch_half = 1 + m * m * inv;
  Real half = 2 * Sqr(sh_half), sh = 2 * sh_half * ch_half;
  Real dx = f.x0 * half + f.r0 * sh, root = f.r0 * (1 + half) + f.x0 * sh;
  Real v = f.start + std::copysign(dx, e) / f.k;
  // Rounding may step past an end: clamped, with the density where it lands.
  bool below = v < f.tmin, above = v > f.tmax;
  Real vc = Pick<kLanes>(below, f.tmin, Pick<kLanes>(above, f.tmax, v));
  Real pdf = f.k / (f.total * Pick<kLanes>(below, f.sa, Pick<kLanes>(above, f.sb, root)));
  Real length = f.tmax - f.tmin, uniform_t = f.tmin + u * length;
  bool uniform = f.k == 0;
  uniform_t = Pick<kLanes>(uniform_t > f.tmax, f.tmax, uniform_t);
  return {Pick<kLanes>(uniform, uniform_t, vc), Pick<kLanes>(uniform, 1 / length, pdf)};
}

}  // namespace detail

template <typename R = float>
class VrlPoint {
 public:
  using Real = R;
  explicit VrlPoint(const VrlPointQuery<Real>& q) : VrlPoint(q, Validate(q)) {}

  // Step one of a medium-to-medium gather: the VRL against the camera segment's line. The
  // whole gather query is validated (Validate(MediumGatherQuery)), as every step is; a
  // valid gather query makes a valid VrlPointQuery.
  explicit VrlPoint(const MediumGatherQuery<Real>& q) : VrlPoint(LineQuery(q.camera, q.vrl), Validate(q)) {}
  // The same for a gather query the caller has validated.
  VrlPoint(ValidQuery, const MediumGatherQuery<Real>& q) : VrlPoint(LineQuery(q.camera, q.vrl), QueryError::None) {}

  bool valid() const { return error_ == QueryError::None; }
  QueryError error() const { return error_; }

  static VrlPointQuery<Real> LineQuery(const RaySegment<Real>& camera, const VrlSegment<Real>& vrl) {
    return {vrl.origin, vrl.dir, 0, vrl.length, camera.origin, camera.dir};
  }

 private:
  // error: Validate of the query this one was built from.
  VrlPoint(const VrlPointQuery<Real>& q, QueryError error) : error_(error) {
    density_.tmin = q.tmin;
    density_.tmax = q.tmax;
    if (valid() && representable()) density_ = detail::FitVrlPointDensity<false>(q);
  }

 public:
  Real sample(Real u) const { return sample_pdf(u).t; }

  Real pdf(Real v) const {
    const detail::VrlPointDensity<Real>& f = density_;
    if (!valid() || !(v >= f.tmin && v <= f.tmax) || !representable()) return 0;
    if (f.k == 0) return 1 / (f.tmax - f.tmin);
    Real x = f.xa + f.k * (v - f.tmin);
    return f.k / (f.total * std::sqrt(1 + x * x));
  }

  // The density from the sample's hyperbolic functions: sqrt(1 + x^2) = cosh(asinh(x)).
  SegmentSample<Real> sample_pdf(Real u) const {
    if (!valid()) return {kNaN, 0};
    if (!representable()) return {density_.tmin, 0};
    return detail::SampleVrlPointDensity<false>(density_, u);
  }

  Real invert(Real v) const {
    const detail::VrlPointDensity<Real>& f = density_;
    if (!valid()) return kNaN;
    if (!representable()) return 0;
    v = Clamp(v, f.tmin, f.tmax);
    if (f.k == 0) return (v - f.tmin) / (f.tmax - f.tmin);
    return Clamp(AsinhDifference(f.xa, f.k * (v - f.tmin)) / f.total, Real(0), Real(1));
  }

  // The fitted density, for samplers that take many samples at once in lanes
  // (detail::SampleVrlPointDensity<true>); meaningful only where valid() and representable().
  const detail::VrlPointDensity<Real>& density() const { return density_; }
  // Whether the VRL is long enough for a density (else sample_pdf gives tmin with pdf 0).
  bool representable() const { return RepresentableLength(density_.tmax - density_.tmin); }

 private:
  static constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();

  QueryError error_;
  detail::VrlPointDensity<Real> density_;
};

// The float lanes of one vector (AVX): SampleVrlPoints runs whole vectors of them.
inline constexpr int kVrlPointBatch = 8;

namespace detail {
// count gathers rounded up to whole vectors of lanes.
inline int WholeLanes(int count) { return (count + kVrlPointBatch - 1) / kVrlPointBatch * kVrlPointBatch; }

// VRLs as one array per number, the layout vector loads want, over whole vectors of lanes
// (the unused lanes repeat the first VRL).
template <typename Real, int kSize>
struct VrlLanes {
  Real ox[kSize], oy[kSize], oz[kSize], dx[kSize], dy[kSize], dz[kSize], length[kSize];

  VrlLanes(const VrlSegment<Real>* vrls, int count) {
    for (int i = 0; i < WholeLanes(count); ++i) {
      const VrlSegment<Real>& vrl = vrls[i < count ? i : 0];
      ox[i] = vrl.origin.x, oy[i] = vrl.origin.y, oz[i] = vrl.origin.z;
      dx[i] = vrl.dir.x, dy[i] = vrl.dir.y, dz[i] = vrl.dir.z;
      length[i] = vrl.length;
    }
  }
  VrlSegment<Real> operator[](int i) const { return {{ox[i], oy[i], oz[i]}, {dx[i], dy[i], dz[i]}, length[i]}; }
};
}  // namespace detail

// Step one for count (1 to kMax) VRLs against one camera segment's line, each a valid gather
// query with it: out[i] is VrlPoint(vrls[i]).sample_pdf(u[i]) to rounding (the lanes take
// square roots by Newton steps, VrlPoint by the instruction). The VRLs are independent, so
// the fit and the sample run as one loop over lanes that compilers vectorise, in whole
// vectors of kVrlPointBatch (the unused lanes repeat the first VRL); several vectors' chains
// overlap in the processor (SampleMediumGathers takes kGatherChunk at once).
template <int kMax = kVrlPointBatch, typename Real>
void SampleVrlPoints(ValidQuery, const RaySegment<Real>& camera, const VrlSegment<Real>* vrls, int count,
                     const Real* u, SegmentSample<Real>* out) {
  static_assert(kMax % kVrlPointBatch == 0, "whole vectors");
  const int lanes = detail::WholeLanes(count);
  const detail::VrlLanes<Real, kMax> vrl(vrls, count);
  Real uu[kMax];
  for (int i = 0; i < lanes; ++i) uu[i] = u[i < count ? i : 0];
  Real t[kMax], pdf[kMax];
  for (int i = 0; i < lanes; ++i) {
    VrlPointQuery<Real> q = VrlPoint<Real>::LineQuery(camera, vrl[i]);
    SegmentSample<Real> s = detail::SampleVrlPointDensity<true>(detail::FitVrlPointDensity<true>(q), uu[i]);
    bool representable = RepresentableLength(vrl.length[i]);  // else tmin with pdf 0, as VrlPoint
    t[i] = SelectLanes(representable, s.t, Real(0));
    pdf[i] = SelectLanes(representable, s.pdf, Real(0));
  }
  for (int i = 0; i < count; ++i) out[i] = {t[i], pdf[i]};
}

// Its entry in the run-time sampler tables (method.hpp).
struct VrlPointEntry {
  static constexpr std::string_view kName = "vrl-point";
  template <typename Real>
  using Sampler = VrlPoint<Real>;
};

}  // namespace vrlis
