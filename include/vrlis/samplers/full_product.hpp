#pragma once
// vrlis's own camera-segment sampler: Novák's piecewise-linear construction applied to the
// full angle-dependent integrand (both phase lobes and both transmittances) instead of the
// phase product alone, with 16 nodes and a positivity floor.
//
// Why: with any extinction the transmittance, which every published sampler ignores,
// decides where the integrand lives; on unbounded segments Novák's phase-only fit can do
// worse than equiangular sampling. Each node costs one more exp and one point on the
// segment. With sigma_t = 0 this is Novák's sampler with 16 nodes and the floor.
#include "novak.hpp"

namespace vrlis {

template <typename Real = float, int kNodes = 16>
using FullProduct = SegmentSampler<PiecewiseLinearAngle<Real, kNodes, FullProductTarget<Real>>>;

}  // namespace vrlis
