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
using CameraSamplersIn = vrlis::SegmentSamplers::Samplers<Real>;
// Every camera sampler in float and in double, for TEMPLATE_LIST_TEST_CASE.
using CameraSamplerTypes =
    decltype(std::tuple_cat(std::declval<CameraSamplersIn<float>>(), std::declval<CameraSamplersIn<double>>()));

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
void ForEachCameraSampler(F&& f) {
  ForEachType(static_cast<CameraSamplersIn<Real>*>(nullptr), f);
}

// The position of S in a tuple of types, -1 if absent.
template <typename S, typename... Types>
constexpr int IndexIn(std::tuple<Types...>*) {
  int index = 0, found = -1;
  ((found = std::is_same_v<S, Types> ? index : found, ++index), ...);
  return found;
}

// The registry's name of sampler S ("novak", "vrl-point"): method.hpp holds the one name table.
template <typename S>
std::string SamplerName() {
  using Real = typename S::Real;
  constexpr int camera = IndexIn<S>(static_cast<CameraSamplersIn<Real>*>(nullptr));
  constexpr int vrl = IndexIn<S>(static_cast<vrlis::VrlSamplers::Samplers<Real>*>(nullptr));
  static_assert(camera >= 0 || vrl >= 0, "not a registered sampler");
  if constexpr (camera >= 0) return std::string(vrlis::SegmentSamplers::kNames[camera]);
  else return std::string(vrlis::VrlSamplers::kNames[vrl]);
}

// Whether sample() is the inverse of invert(): all but the mixture, which picks a component
// first (see cauchy_mixture.hpp); its round trip is tested in distribution instead.
template <typename S>
constexpr bool RoundTripsPointwise() { return !std::is_same_v<S, vrlis::CauchyMixture<typename S::Real>>; }

}  // namespace vrlis::test
