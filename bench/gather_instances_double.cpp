// GatherBatchDouble's batches (bench_gather.cpp) for the lab built on the installed package.
#include <vrlis/gather/gather_instances.hpp>

VRLIS_INSTANTIATE_GATHERS(double)
