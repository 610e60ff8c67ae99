#pragma once
// Every sampler pair's batches in float and double, compiled once for the suite
// (tests/gather/CMakeLists.txt): the files that gather declare them here.
#include <vrlis/gather/gather_instances.hpp>

VRLIS_EXTERN_GATHERS(float)
VRLIS_EXTERN_GATHERS(double)
