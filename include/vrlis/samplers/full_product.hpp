#pragma once
// vrlis's own camera-segment sampler: Novák's piecewise-linear construction applied to the
// full angle-dependent integrand (both phase lobes and both transmittances) instead of the
// phase product alone, with a positivity floor.
//
// Why: with any extinction the transmittance, which every published sampler ignores,
// decides where the integrand lives; on unbounded segments Novák's phase-only fit can do
// worse than equiangular sampling. Each node costs one more exp and one point on the
// segment. With sigma_t = 0 this is Novák's sampler with fewer nodes and the floor.
//
// Eight nodes by default, split at the point lobe's peak and at the peak of segment lobe x
// transmittance (angle/full_product.hpp): on long segments at g < 0 the latter holds most of
// the integral, and without a node there the fit's worst weight reached ~1000 x the
// integral (tests/auto/full_product_peak.cpp). Eight rather than six nodes cut the relative
// variance of those configurations about threefold for a third more fitting work.
#include <string_view>

#include "novak.hpp"

namespace vrlis {

template <typename Real = float, int kNodes = 8>
using FullProduct = SegmentSampler<PiecewiseLinearAngle<Real, kNodes, FullProductTarget<Real>>>;

// Its entry in the run-time sampler tables (method.hpp).
struct FullProductEntry {
  static constexpr std::string_view kName = "full-product";
  template <typename Real>
  using Sampler = FullProduct<Real>;
};

}  // namespace vrlis
