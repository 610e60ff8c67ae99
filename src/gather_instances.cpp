// The repository's one compilation of the batched gathers in VRLIS_GATHER_REAL (one object
// library per Real, CMakeLists.txt), for every target that declares them extern.
#include <vrlis/gather/gather_instances.hpp>

VRLIS_INSTANTIATE_GATHERS(VRLIS_GATHER_REAL)
