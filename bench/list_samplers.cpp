// vrlis_samplers: prints the registries' samplers with their roles in the lab (sampler_roles.hpp)
// as JSON, the table tools/samplers.py gives every script and chart. No Embree, no renderer:
// a build of seconds, even for tools/speed.sh's tree under test.
#include <cstdio>

#include "sampler_roles.hpp"

int main() {
  std::fputs(vrlis::lab::Listing().c_str(), stdout);
  return 0;
}
