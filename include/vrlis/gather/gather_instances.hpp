#pragma once
// The batched gathers of every registered sampler pair in one Real, as explicit template
// instances, for a renderer whose translation units call GatherMediumVrls / GatherSurfaceVrls
// (or the batches themselves) with the samplers chosen at run time: each such file otherwise
// compiles every pair, twice (core/dispatch.hpp), about a minute of g++ apiece. Declare them
// where the gathers are called, define them in one source file:
//   VRLIS_EXTERN_GATHERS(float)       // in a header, or every file that gathers
//   VRLIS_INSTANTIATE_GATHERS(float)  // in one .cpp
// A sampler missing from the list would still work, compiled where it is used; the count
// below makes a newly registered one a compile error until it is listed.
#include "../method.hpp"
#include "medium_gather.hpp"
#include "surface_gather.hpp"

static_assert(vrlis::SegmentSamplers::kCount == 6 && vrlis::VrlSamplers::kCount == 2,
              "list every registered sampler in VRLIS_GATHER_INSTANCES_ (gather/gather_instances.hpp)");

#define VRLIS_MEDIUM_GATHER_INSTANCE_(kind, StepOne, Camera, Real)                                                  \
  kind template void vrlis::SampleMediumGathers<vrlis::StepOne::Sampler<Real>, vrlis::Camera::Sampler<Real>, Real>( \
      vrlis::ValidQuery, const vrlis::RaySegment<Real>&, const vrlis::Medium<Real>&, const vrlis::VrlSegment<Real>*, \
      int, const Real*, const Real*, vrlis::GatherSample<Real>*, bool, bool, const bool*);
#define VRLIS_SURFACE_GATHER_INSTANCE_(kind, Camera, Real)                                                          \
  kind template void vrlis::SampleSurfaceGathers<vrlis::Camera::Sampler<Real>, Real>(                               \
      vrlis::ValidQuery, vrlis::Vec3<Real>, vrlis::Vec3<Real>, const vrlis::Medium<Real>&,                          \
      const vrlis::VrlSegment<Real>*, int, const Real*, vrlis::GatherSample<Real>*, bool, bool);
// A camera sampler's gathers: after each step one (VrlSamplers), and at a surface.
#define VRLIS_CAMERA_GATHER_INSTANCES_(kind, Camera, Real)            \
  VRLIS_MEDIUM_GATHER_INSTANCE_(kind, VrlPointEntry, Camera, Real)    \
  VRLIS_MEDIUM_GATHER_INSTANCE_(kind, VrlMarginalEntry, Camera, Real) \
  VRLIS_SURFACE_GATHER_INSTANCE_(kind, Camera, Real)
// Every camera sampler of SegmentSamplers (method.hpp).
#define VRLIS_GATHER_INSTANCES_(kind, Real)                      \
  VRLIS_CAMERA_GATHER_INSTANCES_(kind, EquiangularEntry, Real)   \
  VRLIS_CAMERA_GATHER_INSTANCES_(kind, NovakEntry, Real)         \
  VRLIS_CAMERA_GATHER_INSTANCES_(kind, CauchySumEntry, Real)     \
  VRLIS_CAMERA_GATHER_INSTANCES_(kind, CauchyMixtureEntry, Real) \
  VRLIS_CAMERA_GATHER_INSTANCES_(kind, FullProductEntry, Real)   \
  VRLIS_CAMERA_GATHER_INSTANCES_(kind, AutoEntry, Real)

// The gathers in Real compiled elsewhere (VRLIS_INSTANTIATE_GATHERS): calls here link to them.
#define VRLIS_EXTERN_GATHERS(Real) VRLIS_GATHER_INSTANCES_(extern, Real)
// The gathers in Real compiled here, for every file that declares them extern.
#define VRLIS_INSTANTIATE_GATHERS(Real) VRLIS_GATHER_INSTANCES_(, Real)
