// The batched medium-to-medium gathers in float, compiled once for vrlis_bench (gather_instances.hpp).
#define VRLIS_BENCH_GATHER_INSTANCES
#include "gather_instances.hpp"

VRLIS_BENCH_GATHERS()
