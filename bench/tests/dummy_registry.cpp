// A stand-in for vrlis_samplers whose segment-sampler table has one more entry: a dummy
// sampler registered the way a new one is (its entry, one line in the registry), with roles in
// the lab (sampler_roles.hpp) and a library property of its own. tools_list_dummy.py checks
// that every script reading the listing lists it.
#include <cstdio>

#include "sampler_roles.hpp"

namespace {

struct DummyEntry {
  static constexpr std::string_view kName = "dummy-sampler";
  static constexpr bool kRoundTripInDistribution = true;
  template <typename Real>
  using Sampler = vrlis::Equiangular<Real>;
};

template <typename Registry, typename Entry>
struct Append;
template <typename... Entries, typename Entry>
struct Append<vrlis::Registry<Entries...>, Entry> {
  using type = vrlis::Registry<Entries..., Entry>;
};

using WithDummy = Append<vrlis::SegmentSamplers, DummyEntry>::type;

// The registry takes the entry's property and finds it by name like any other.
static_assert(WithDummy::kRoundTripInDistribution.back());
static_assert(WithDummy::Parse("dummy-sampler") == WithDummy::Of<DummyEntry>());

}  // namespace

namespace vrlis::lab {
template <>
inline constexpr bool kOwn<DummyEntry> = true;
template <>
inline constexpr bool kThesis<DummyEntry> = true;
}  // namespace vrlis::lab

int main() {
  std::fputs(vrlis::lab::Listing<WithDummy>().c_str(), stdout);
  return 0;
}
