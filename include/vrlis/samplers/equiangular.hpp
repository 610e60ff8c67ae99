#pragma once
// Equiangular sampling (Kulla and Fajardo 2012): uniform in theta. Exact for isotropic
// media and the cost floor every other sampler is measured against.
#include <string_view>

#include "../angle/segment_sampler.hpp"

namespace vrlis {

template <typename R>
class UniformAngle {
 public:
  using Real = R;
  UniformAngle(const SegmentQuery<Real>&, const AngleDomain<Real>& dom) : UniformAngle(dom.width()) {}
  explicit UniformAngle(Real width) : width_(width) {}
  Real sample(Real u) const { return u * width_; }
  Real pdf(Real) const { return 1 / width_; }
  Real cdf(Real delta) const { return delta / width_; }
  SegmentSample<Real> sample_pdf(Real u) const { return {sample(u), pdf(0)}; }

 private:
  Real width_;
};

template <typename Real = float>
using Equiangular = SegmentSampler<UniformAngle<Real>>;

// Its entry in the run-time sampler tables (method.hpp).
struct EquiangularEntry {
  static constexpr std::string_view kName = "equiangular";
  template <typename Real>
  using Sampler = Equiangular<Real>;
};

}  // namespace vrlis
