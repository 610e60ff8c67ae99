#pragma once
// Which parts of light transport a render computes (see docs/renderer.md for how the parts
// add up to the whole without counting a path twice).
#include <vrlis/effort/policy.hpp>
#include <vrlis/method.hpp>

#include "share.hpp"

namespace vrlis::integration {

class QueryLog;
class WeightLog;

struct TransportSettings {
  // How every VRL gather samples: step one and step two of the medium-to-medium gather; the
  // medium-to-surface gather and single scattering use its camera sampler.
  vrlis::GatherSamplers sampling;
  bool medium_to_medium = true;   // VRL gather along camera segments
  bool medium_to_surface = true;  // VRL gather at the diffuse surface ending the camera chain
  bool direct = true;             // next-event estimation at the first camera vertex
  // With direct: also single scattering along camera segments (off: the surface part alone;
  // the comparison's noise decomposition takes the two apart).
  bool single_scattering = true;
  bool indirect = true;           // path-traced remainder (the connections the gathers leave it)
  // VPLs at the light paths' diffuse vertices (vpl.hpp), gathered at the diffuse point ending
  // the camera chain (surface to surface) and along camera segments (surface to medium): the
  // connections up to the geometry term `vpl_bound`, the remainder carrying the excess. With
  // vpl_bound = 0 the remainder carries them all.
  bool surface_to_surface = true;
  bool surface_to_medium = true;
  float vpl_bound = 1;
  // VPLs each of those gathers connects, chosen in proportion to flux; with the effort control
  // on, as many as its price asks once it has one (docs/maths.md#effort-split).
  int vpl_samples = 8;
  // The VRL gathers' connections the same way (share.hpp): each up to the geometry term
  // `vrl_bound` (1 / r^2 medium to medium, cos / r^2 medium to surface), the remainder
  // sampling the camera vertex's next medium segment for the excess. kUnbounded: the gathers
  // carry every connection whole (a scene whose VRLs pass close to surfaces or the camera's
  // segments sets a bound: corner).
  float vrl_bound = kUnbounded;
  // In path-traced parts, light of point lights inside the medium scattered once and then at a
  // scattering vertex is sampled jointly from the vertex (off: along the next segment, whose
  // weight has unbounded variance next to the light; docs/maths.md#two-point).
  bool vertex_single_scattering = true;
  // Light paths that meet a specular surface before any diffuse or medium vertex (L S+ ...)
  // may go on. Off, the VRL image holds exactly what a path tracer with next-event
  // estimation can sample from point and collimated lights.
  bool light_caustics = true;
  bool first_segment_only = false;  // light paths stop after their first medium segment
  int max_depth = 100;              // interactions per path (camera or light side)
  int rr_depth = 3;                 // Russian roulette from this depth on
  QueryLog* query_log = nullptr;    // if set, records a sample of the medium-to-medium gathers
  WeightLog* weight_log = nullptr;  // if set, records the weights of every VRL gather sample taken
  // The effort control of both VRL gathers, on with the default samplers (off: every VRL
  // gathered once); its price is the renderer's, learned pass by pass (vrlis/effort/price.hpp).
  vrlis::EffortSettings effort{true};
  // With VrlMarginal as step one: the share of the medium-to-medium gathers, those of the
  // largest predicted second moments, that take its fit; the rest take VrlPoint's density.
  // The renderer sets effort.marginal_threshold to it pass by pass from the scores of the
  // passes before (the first pass fits every gather; docs/maths.md#vrl-marginal-where). 1:
  // every gather fitted, in every pass.
  double marginal_fraction = 0.2;
};

}  // namespace vrlis::integration
