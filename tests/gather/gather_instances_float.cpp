// The batched gathers in float, compiled once for the suite (gather_instances.hpp).
#define VRLIS_TEST_GATHER_INSTANCES
#include "gather_instances.hpp"

VRLIS_TEST_GATHERS(, float)
