#pragma once
// The batched medium-to-medium gathers in float, every step one x camera sampler, compiled
// once for vrlis_bench (gather_instances.cpp): bench_gather.cpp and bench_work.cpp both reach
// all of them, and each compiles them twice (core/dispatch.hpp), over a minute apiece.
// As tests/gather/gather_instances.hpp: a sampler missing here would still work, compiled
// where it is used; the count below makes a newly registered one a compile error until listed.
#include <vrlis/vrlis.hpp>

static_assert(vrlis::SegmentSamplers::kCount == 6 && vrlis::VrlSamplers::kCount == 2,
              "list every registered sampler in VRLIS_BENCH_GATHERS (below)");

#define VRLIS_BENCH_MEDIUM_GATHERS(kind, StepOne, Camera)                                                          \
  kind template void vrlis::SampleMediumGathers<vrlis::StepOne::Sampler<float>, vrlis::Camera::Sampler<float>, float>( \
      vrlis::ValidQuery, const vrlis::RaySegment<float>&, const vrlis::Medium<float>&,                             \
      const vrlis::VrlSegment<float>*, int, const float*, const float*, vrlis::GatherSample<float>*, bool, bool,    \
      const bool*);
#define VRLIS_BENCH_GATHERS_OF(kind, Camera)                 \
  VRLIS_BENCH_MEDIUM_GATHERS(kind, VrlPointEntry, Camera)    \
  VRLIS_BENCH_MEDIUM_GATHERS(kind, VrlMarginalEntry, Camera)
#define VRLIS_BENCH_GATHERS(kind)                   \
  VRLIS_BENCH_GATHERS_OF(kind, EquiangularEntry)    \
  VRLIS_BENCH_GATHERS_OF(kind, NovakEntry)          \
  VRLIS_BENCH_GATHERS_OF(kind, CauchySumEntry)      \
  VRLIS_BENCH_GATHERS_OF(kind, CauchyMixtureEntry)  \
  VRLIS_BENCH_GATHERS_OF(kind, FullProductEntry)    \
  VRLIS_BENCH_GATHERS_OF(kind, AutoEntry)

#ifndef VRLIS_BENCH_GATHER_INSTANCES
VRLIS_BENCH_GATHERS(extern)
#endif
