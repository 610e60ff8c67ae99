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
// Six nodes by default: in the whole two-step estimator the VRL point leaves a relative
// variance of ~0.1-1, so the camera step only needs to be well below that. With sigma_t = 1
// six nodes give 0.002-0.03 for |g| <= 0.9 (Novák's ten: 0.04-0.16) at 0.9x Novák's cost;
// sixteen give 1e-6-1e-3 at 1.7x (tools/bench.sh measures both ends).
#include <string_view>

#include "novak.hpp"

namespace vrlis {

template <typename Real = float, int kNodes = 6>
using FullProduct = SegmentSampler<PiecewiseLinearAngle<Real, kNodes, FullProductTarget<Real>>>;

// Its entry in the run-time sampler tables (method.hpp).
struct FullProductEntry {
  static constexpr std::string_view kName = "full-product";
  template <typename Real>
  using Sampler = FullProduct<Real>;
};

}  // namespace vrlis
