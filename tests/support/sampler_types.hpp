#pragma once
// The samplers under test, taken from the library's registries (method.hpp): type lists,
// names and the one property the checks must know. A newly registered sampler is tested by
// every test that iterates these, with no edit to the tests. Standard library and vrlis
// only (the fuzz target includes it too).
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include <vrlis/method.hpp>

namespace vrlis::test {

template <typename Real>
using SegmentSamplersIn = vrlis::SegmentSamplers::Samplers<Real>;
// Every camera sampler in float and in double, for TEMPLATE_LIST_TEST_CASE.
using SegmentSamplerTypes =
    decltype(std::tuple_cat(std::declval<SegmentSamplersIn<float>>(), std::declval<SegmentSamplersIn<double>>()));

template <typename S>
struct Tag {
  using type = S;
};

template <typename... S, typename F>
void ForEachType(std::tuple<S...>*, F& f) {
  (f(Tag<S>{}), ...);
}

// Calls f(Tag<S>{}) for every camera sampler S in precision Real.
template <typename Real, typename F>
void ForEachSegmentSampler(F&& f) {
  ForEachType(static_cast<SegmentSamplersIn<Real>*>(nullptr), f);
}

// The position of S in a tuple of types, -1 if absent.
template <typename S, typename... Types>
constexpr int IndexIn(std::tuple<Types...>*) {
  int index = 0, found = -1;
  ((found = std::is_same_v<S, Types> ? index : found, ++index), ...);
  return found;
}

// Calls f(registry, index) for the registry and position of sampler S.
template <typename S, typename F>
constexpr decltype(auto) WithRegistryOf(F&& f) {
  using Real = typename S::Real;
  constexpr int segment = IndexIn<S>(static_cast<SegmentSamplersIn<Real>*>(nullptr));
  constexpr int vrl = IndexIn<S>(static_cast<vrlis::VrlSamplers::Samplers<Real>*>(nullptr));
  static_assert(segment >= 0 || vrl >= 0, "not a registered sampler");
  if constexpr (segment >= 0) return f(vrlis::Type<vrlis::SegmentSamplers>{}, std::size_t(segment));
  else return f(vrlis::Type<vrlis::VrlSamplers>{}, std::size_t(vrl));
}

// The registry's name of sampler S ("novak", "vrl-point"): method.hpp holds the one name table.
template <typename S>
std::string SamplerName() {
  return WithRegistryOf<S>([](auto registry, std::size_t i) { return std::string(decltype(registry)::type::kNames[i]); });
}

// Whether sample() is the inverse of invert() pointwise (the registry's property; where it
// holds in distribution only, the round trip is tested in distribution instead).
template <typename S>
constexpr bool RoundTripsPointwise() {
  return WithRegistryOf<S>([](auto registry, std::size_t i) { return !decltype(registry)::type::kRoundTripInDistribution[i]; });
}

}  // namespace vrlis::test
