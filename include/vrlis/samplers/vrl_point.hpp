#pragma once
// Step one of Novák's estimator: a point on the VRL with density proportional to the
// inverse distance from the VRL point to the camera line (section 2 of the maths note),
//   p(v) proportional to 1 / sqrt(1 + x(v)^2),  x(v) = k (v - v0),  k = sin(a) / h.
// The CDF is asinh(x(v)) - asinh(x(tmin)), computed without cancellation.
//
// Contract: valid() is false for non-finite input (tmax too: the density's tail makes an
// unbounded VRL unnormalisable), non-unit directions, tmax < tmin and coordinates beyond
// MaxCoordinate<Real>(); then sample() and
// invert() return NaN and pdf() returns 0. Parallel lines give the uniform density (the
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

template <typename R = float>
class VrlPoint {
 public:
  using Real = R;
  explicit VrlPoint(const VrlPointQuery<Real>& q) : tmin_(q.tmin), tmax_(q.tmax) {
    valid_ = IsFinite(q.origin) && IsFinite(q.dir) && IsFinite(q.line_origin) && IsFinite(q.line_dir) &&
             std::isfinite(q.tmin) && std::isfinite(q.tmax) && q.tmax >= q.tmin &&
             std::abs(Dot(q.dir, q.dir) - 1) <= Real(2e-3) && std::abs(Dot(q.line_dir, q.line_dir) - 1) <= Real(2e-3) &&
             detail::InRange(q.origin) && detail::InRange(q.line_origin) && std::abs(q.tmin) <= MaxCoordinate<Real>() &&
             std::abs(q.tmax) <= MaxCoordinate<Real>();
    if (!valid_ || !Representable()) return;
    Vec3<Real> d = q.line_origin - q.origin, cross = Cross(q.dir, q.line_dir);
    Real sin_a = Length(cross);
    Real along = Dot(d, q.dir);
    if (!(sin_a > 0)) return;  // parallel: uniform
    Real h = std::abs(Dot(d, cross)) / sin_a;
    h = std::max(h, NoiseFloor(Length(d) + std::abs(tmin_) + std::abs(tmax_)));
    Real v0 = (along - Dot(d, q.line_dir) * Dot(q.dir, q.line_dir)) / Sqr(sin_a);
    k_ = sin_a / h;
    // The density varies by at most k L / 2 over the VRL: below epsilon it is uniform, and
    // the asinh difference of a subnormal k L would have no digits left.
    if (!(k_ * (tmax_ - tmin_) > std::numeric_limits<Real>::epsilon())) {
      k_ = 0;
      return;
    }
    xa_ = k_ * (tmin_ - v0);
    total_ = AsinhDifference(xa_, k_ * (tmax_ - tmin_));
    if (!(total_ > 0) || !std::isfinite(total_)) k_ = 0;  // uniform to the last digit
  }

  // Step one of a medium-to-medium gather: the VRL against the camera segment's line.
  explicit VrlPoint(const MediumGatherQuery<Real>& q)
      : VrlPoint(VrlPointQuery<Real>{q.vrl.origin, q.vrl.dir, 0, q.vrl.length, q.camera.origin, q.camera.dir}) {}

  bool valid() const { return valid_; }

  Real sample(Real u) const {
    if (!valid_) return kNaN;
    Real length = tmax_ - tmin_;
    if (!Representable()) return tmin_;
    if (k_ == 0) return std::min(tmin_ + u * length, tmax_);
    Real d = u * total_, xb = xa_ + k_ * length, v;
    if (xb <= 0)  // v0 at or beyond tmax: step back from tmax, where the density peaks
      v = tmax_ - Advance(-xb, total_ - d) / k_;
    else
      v = tmin_ + Advance(xa_, d) / k_;
    return Clamp(v, tmin_, tmax_);
  }

  Real pdf(Real v) const {
    if (!valid_ || !(v >= tmin_ && v <= tmax_) || !Representable()) return 0;
    if (k_ == 0) return 1 / (tmax_ - tmin_);
    Real x = xa_ + k_ * (v - tmin_);
    return k_ / (total_ * std::sqrt(1 + x * x));
  }

  SegmentSample<Real> sample_pdf(Real u) const {
    Real v = sample(u);
    return {v, pdf(v)};
  }

  Real invert(Real v) const {
    if (!valid_) return kNaN;
    if (!Representable()) return 0;
    v = Clamp(v, tmin_, tmax_);
    if (k_ == 0) return (v - tmin_) / (tmax_ - tmin_);
    return Clamp(AsinhDifference(xa_, k_ * (v - tmin_)) / total_, Real(0), Real(1));
  }

 private:
  static constexpr Real kNaN = std::numeric_limits<Real>::quiet_NaN();
  bool Representable() const { return RepresentableLength(tmax_ - tmin_); }
  // sinh(asinh(x0) + d) - x0 for d >= 0, as a sum of positive terms and one expm1 (sinh,
  // asinh and a second sinh cost three libm calls): with E = expm1(d), cosh d - 1 =
  // E^2 / (2 (E + 1)) and sinh d = E (E + 2) / (2 (E + 1)), so the difference
  // x0 (cosh d - 1) + sqrt(1 + x0^2) sinh d = E / (E + 1) ((x0 + s0) E + 2 s0) / 2, where
  // x0 + s0 = 1 / (s0 - x0) for x0 < 0 keeps its digits.
  static Real Advance(Real x0, Real d) {
    Real e = std::expm1(d), s0 = std::sqrt(1 + x0 * x0);
    Real x0_plus_s0 = x0 >= 0 ? x0 + s0 : 1 / (s0 - x0);
    return e / (e + 1) * (x0_plus_s0 * e + 2 * s0) / 2;
  }

  Real tmin_, tmax_;
  bool valid_ = false;
  Real k_ = 0, xa_ = 0, total_ = 0;
};

// Its entry in the run-time sampler tables (method.hpp).
struct VrlPointEntry {
  static constexpr std::string_view kName = "vrl-point";
  template <typename Real>
  using Sampler = VrlPoint<Real>;
};

}  // namespace vrlis
