#pragma once
// What one gather call takes besides its queries when the effort control (or VrlMarginal's
// choice of fits) acts: the settings, each VRL's predicted weight, and where the call adds
// what it learned. EffortPrice::Pixel hands these out ready-made (price.hpp).
#include "marginal_fits.hpp"
#include "policy.hpp"
#include "record.hpp"
#include "work_costs.hpp"

namespace vrlis {

template <typename Real>
struct EffortCall {
  EffortSettings settings;
  // weights[i] >= 0 scales VRL i's predicted contribution (its power times the camera path's
  // throughput, in the units of the contributions the visitor returns); null: all 1.
  const Real* weights = nullptr;
  // If set, the call adds its samples' statistics and counted work (record.hpp); then the
  // visitor returns the contribution it added.
  EffortRecord* record = nullptr;
  // If set, with VrlMarginal as step one, the gathers' MarginalFitScores.
  ScoreOctaves* scores = nullptr;
  // The counted work of one visit of a sample of positive weight, the renderer's (its
  // occlusion ray and connection; a sample of zero weight contributes nothing and is counted
  // as needing no ray): the default is the example renderer's on its scenes (work_costs.hpp).
  double visit_work = work_costs::kVisit;
};

}  // namespace vrlis
