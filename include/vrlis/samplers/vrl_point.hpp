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

template <typename R = float>
class VrlPoint {
 public:
  using Real = R;
  explicit VrlPoint(const VrlPointQuery<Real>& q) : VrlPoint(q, Validate(q)) {}

  // Step one of a medium-to-medium gather: the VRL against the camera segment's line. The
  // whole gather query is validated (Validate(MediumGatherQuery)), as every step is; a
  // valid gather query makes a valid VrlPointQuery.
  explicit VrlPoint(const MediumGatherQuery<Real>& q) : VrlPoint(LineQuery(q), Validate(q)) {}
  // The same for a gather query the caller has validated.
  VrlPoint(ValidQuery, const MediumGatherQuery<Real>& q) : VrlPoint(LineQuery(q), QueryError::None) {}

  bool valid() const { return error_ == QueryError::None; }
  QueryError error() const { return error_; }

 private:
  static VrlPointQuery<Real> LineQuery(const MediumGatherQuery<Real>& q) {
    return {q.vrl.origin, q.vrl.dir, 0, q.vrl.length, q.camera.origin, q.camera.dir};
  }
  // error: Validate of the query this one was built from.
  VrlPoint(const VrlPointQuery<Real>& q, QueryError error) : tmin_(q.tmin), tmax_(q.tmax), error_(error) {
    if (!valid() || !Representable()) return;
    Vec3<Real> d = q.line_origin - q.origin, cross = Cross(q.dir, q.line_dir);
    Real sin_a = Length(cross);
    Real along = Dot(d, q.dir);
    if (!(sin_a > 0)) return;  // parallel: uniform
    Real inv_sin_a = 1 / sin_a;
    Real h = std::abs(Dot(d, cross)) * inv_sin_a;
    h = std::max(h, NoiseFloor(Length(d) + std::abs(tmin_) + std::abs(tmax_)));
    Real v0 = (along - Dot(d, q.line_dir) * Dot(q.dir, q.line_dir)) * Sqr(inv_sin_a);
    k_ = sin_a / h;
    // The density varies by at most k L / 2 over the VRL: below epsilon it is uniform, and
    // the asinh difference of a subnormal k L would have no digits left.
    if (!(k_ * (tmax_ - tmin_) > std::numeric_limits<Real>::epsilon())) {
      k_ = 0;
      return;
    }
    xa_ = k_ * (tmin_ - v0);
    Real xb = xa_ + k_ * (tmax_ - tmin_);
    // Sampling walks outward from the point of the VRL nearest the line that the samples
    // reach first: tmin when x >= 0 throughout, tmax when x <= 0, else v0 with the masses
    // on either side of it (so that no walk moves towards v0, where digits cancel).
    if (xa_ >= 0) {
      total_ = AsinhDifference(xa_, k_ * (tmax_ - tmin_));
      walk_ = {tmin_, xa_, 0};
    } else if (xb <= 0) {
      total_ = AsinhDifference(xa_, k_ * (tmax_ - tmin_));
      walk_ = {tmax_, -xb, total_};
    } else {
      Real left = AsinhDifference(Real(0), -xa_);
      total_ = left + AsinhDifference(Real(0), xb);
      walk_ = {v0, 0, left};
    }
    if (!(total_ > 0) || !std::isfinite(total_)) k_ = 0;  // uniform to the last digit
  }

 public:
  Real sample(Real u) const { return sample_pdf(u).t; }

  Real pdf(Real v) const {
    if (!valid() || !(v >= tmin_ && v <= tmax_) || !Representable()) return 0;
    if (k_ == 0) return 1 / (tmax_ - tmin_);
    Real x = xa_ + k_ * (v - tmin_);
    return k_ / (total_ * std::sqrt(1 + x * x));
  }

  // The density from the sample's hyperbolic functions: sqrt(1 + x^2) = cosh(asinh(x)).
  SegmentSample<Real> sample_pdf(Real u) const {
    if (!valid()) return {kNaN, 0};
    Real length = tmax_ - tmin_;
    if (!Representable()) return {tmin_, 0};
    if (k_ == 0) return {std::min(tmin_ + u * length, tmax_), 1 / length};
    // e: the mass from the walk's start to the sample, signed by the direction of the walk.
    Real e = u * total_ - walk_.mass_before;
    Outward step(walk_.x, std::abs(e));
    Real v = walk_.start + std::copysign(step.dx, e) / k_;
    if (!(v >= tmin_ && v <= tmax_)) {  // clamped: the density where it lands
      v = Clamp(v, tmin_, tmax_);
      return {v, pdf(v)};
    }
    return {v, k_ / (total_ * step.root)};
  }

  Real invert(Real v) const {
    if (!valid()) return kNaN;
    if (!Representable()) return 0;
    v = Clamp(v, tmin_, tmax_);
    if (k_ == 0) return (v - tmin_) / (tmax_ - tmin_);
    return Clamp(AsinhDifference(xa_, k_ * (v - tmin_)) / total_, Real(0), Real(1));
  }

 private:
  static constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
  bool Representable() const { return RepresentableLength(tmax_ - tmin_); }
  // For x0 >= 0, d >= 0 and x1 = sinh(asinh(x0) + d): x1 - x0 and sqrt(1 + x1^2) = cosh(...),
  // both as sums of positive terms. One expm1 gives both hyperbolic functions of d: with
  // e = expm1(d / 2), sinh(d / 2) = e (e + 2) / (2 (e + 1)) and cosh(d / 2) - 1 = e^2 / (2 (e + 1)),
  // and sinh(d) = 2 sinh(d / 2) cosh(d / 2).
  struct Outward {
    Real dx, root;
    Outward(Real x0, Real d) {
      Real e = Expm1Lanes(d / 2), inv = 1 / (2 * (e + 1));
      Real sh_half = e * (e + 2) * inv, ch_half = 1 + e * e * inv;
      Real half = 2 * Sqr(sh_half), sh = 2 * sh_half * ch_half, r0 = std::sqrt(1 + x0 * x0);
      dx = x0 * half + r0 * sh;
      root = r0 * (1 + half) + x0 * sh;
    }
  };

  Real tmin_, tmax_;
  QueryError error_;
  Real k_ = 0, xa_ = 0, total_ = 0;
  struct Walk {
    Real start, x, mass_before;  // where it starts, |x| there, the CDF there
  } walk_{};
};

// Its entry in the run-time sampler tables (method.hpp).
struct VrlPointEntry {
  static constexpr std::string_view kName = "vrl-point";
  template <typename Real>
  using Sampler = VrlPoint<Real>;
};

}  // namespace vrlis
