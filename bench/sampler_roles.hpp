#pragma once
// The samplers' roles in the lab's studies, which the library's users have no need of: which
// samplers are this project's, which choose among the others, which the thesis proposes and
// which every ratio is to. Listing() prints them with the registries' names for the scripts
// and charts (vrlis_samplers, read by tools/samplers.py), so that no script names a sampler.
#include <string>
#include <type_traits>

#include <vrlis/method.hpp>

namespace vrlis::lab {

// Per registry entry, false unless set here (a new sampler's entry is added where it holds):
// kOwn: this project's sampler rather than a published one (the charts set the two apart);
template <typename Entry>
inline constexpr bool kOwn = false;
template <>
inline constexpr bool kOwn<FullProductEntry> = true;
template <>
inline constexpr bool kOwn<AutoEntry> = true;
template <>
inline constexpr bool kOwn<VrlMarginalEntry> = true;
// kPolicy: it chooses among the other samplers per query, so only the equal-time study judges it;
template <typename Entry>
inline constexpr bool kPolicy = false;
template <>
inline constexpr bool kPolicy<AutoEntry> = true;
// kThesis: proposed by Oppitz's thesis, whose claims the studies test on it.
template <typename Entry>
inline constexpr bool kThesis = false;
template <>
inline constexpr bool kThesis<CauchySumEntry> = true;
template <>
inline constexpr bool kThesis<CauchyMixtureEntry> = true;

// The sampler every efficiency ratio is to: Novák et al.'s, the published state of the art.
using Baseline = NovakEntry;

namespace detail {
template <typename... Entries>
std::string ListEntries(Registry<Entries...>*) {
  std::string json = "[";
  auto flag = [](bool b) { return b ? "true" : "false"; };
  ((json += std::string(json.size() > 1 ? ",\n " : "\n ") + "{\"name\": \"" + std::string(Entries::kName) +
            "\", \"own\": " + flag(kOwn<Entries>) + ", \"policy\": " + flag(kPolicy<Entries>) +
            ", \"thesis\": " + flag(kThesis<Entries>) + ", \"baseline\": " + flag(std::is_same_v<Entries, Baseline>) +
            "}"),
   ...);
  return json + "]";
}
}  // namespace detail

// Both registries as JSON, {"segment": [...], "vrl": [...]}, one object per entry in registry
// order: name, own, policy, thesis, baseline. (Segment: a test's registry with one more entry.)
template <typename Segment = SegmentSamplers>
std::string Listing() {
  return "{\"segment\": " + detail::ListEntries(static_cast<Segment*>(nullptr)) +
         ",\n \"vrl\": " + detail::ListEntries(static_cast<VrlSamplers*>(nullptr)) + "}\n";
}

}  // namespace vrlis::lab
