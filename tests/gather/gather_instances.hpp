#pragma once
// The batched gathers of every registered sampler, compiled once for the whole suite
// (gather_instances.cpp) instead of in every test file that reaches them: each file calling
// GatherMediumVrls compiles all of them twice (core/dispatch.hpp), about a minute apiece.
// A sampler missing here would still work, its gathers compiled where they are used; the
// count below makes a newly registered one a compile error until it is listed.
#include <vrlis/vrlis.hpp>

static_assert(vrlis::SegmentSamplers::kCount == 6 && vrlis::VrlSamplers::kCount == 2,
              "list every registered sampler in VRLIS_TEST_GATHERS (below)");

#define VRLIS_TEST_MEDIUM_GATHERS(kind, StepOne, Camera, Real)                                                     \
  kind template void vrlis::SampleMediumGathers<vrlis::StepOne::Sampler<Real>, vrlis::Camera::Sampler<Real>, Real>( \
      vrlis::ValidQuery, const vrlis::RaySegment<Real>&, const vrlis::Medium<Real>&, const vrlis::VrlSegment<Real>*, \
      int, const Real*, const Real*, vrlis::GatherSample<Real>*, bool, bool, const bool*);
#define VRLIS_TEST_SURFACE_GATHERS(kind, Camera, Real)                                                              \
  kind template void vrlis::SampleSurfaceGathers<vrlis::Camera::Sampler<Real>, Real>(                               \
      vrlis::ValidQuery, vrlis::Vec3<Real>, vrlis::Vec3<Real>, const vrlis::Medium<Real>&,                          \
      const vrlis::VrlSegment<Real>*, int, const Real*, vrlis::GatherSample<Real>*, bool, bool);
#define VRLIS_TEST_GATHERS_OF(kind, Camera, Real)                 \
  VRLIS_TEST_MEDIUM_GATHERS(kind, VrlPointEntry, Camera, Real)    \
  VRLIS_TEST_MEDIUM_GATHERS(kind, VrlMarginalEntry, Camera, Real) \
  VRLIS_TEST_SURFACE_GATHERS(kind, Camera, Real)
// Every camera sampler of SegmentSamplers (method.hpp), with both step ones.
#define VRLIS_TEST_GATHERS(kind, Real)                    \
  VRLIS_TEST_GATHERS_OF(kind, EquiangularEntry, Real)     \
  VRLIS_TEST_GATHERS_OF(kind, NovakEntry, Real)           \
  VRLIS_TEST_GATHERS_OF(kind, CauchySumEntry, Real)       \
  VRLIS_TEST_GATHERS_OF(kind, CauchyMixtureEntry, Real)   \
  VRLIS_TEST_GATHERS_OF(kind, FullProductEntry, Real)     \
  VRLIS_TEST_GATHERS_OF(kind, AutoEntry, Real)

#ifndef VRLIS_TEST_GATHER_INSTANCES
VRLIS_TEST_GATHERS(extern, float)
VRLIS_TEST_GATHERS(extern, double)
#endif
