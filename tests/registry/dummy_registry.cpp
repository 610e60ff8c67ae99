// A stand-in for vrl_render --list-samplers whose segment-sampler table has one more entry:
// a dummy sampler registered the way a new one is (its entry, one line in the registry), with
// properties of its own. tools_list_dummy.py checks that every tool reading the table lists it.
#include <cstdio>

#include <vrlis/method.hpp>

namespace {

struct DummyEntry {
  static constexpr std::string_view kName = "dummy-sampler";
  static constexpr bool kOwn = true, kRoundTripInDistribution = true, kThesis = true;
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

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 || std::string_view(argv[1]) != "--list-samplers") return 2;
  std::printf("{\"segment\": %s,\n \"vrl\": %s}\n", WithDummy::ListJson().c_str(), vrlis::VrlSamplers::ListJson().c_str());
  return 0;
}
