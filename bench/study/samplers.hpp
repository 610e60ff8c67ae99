#pragma once
// The camera samplers of the library's registry (vrlis::SegmentSamplers), all fitted to one
// query at once: the quadrature evaluates every sampler's density at each of its points,
// sharing the integrand. Order and names are the registry's (vrlis::kSegmentSamplers, Name).
#include <tuple>

#include "config.hpp"

namespace vrlis::study {

namespace detail {
template <typename Real, typename... Entries>
std::tuple<typename Entries::template Sampler<Real>...> FitEach(const SegmentQuery<Real>& q, Registry<Entries...>*) {
  return {typename Entries::template Sampler<Real>(q)...};
}
}  // namespace detail

template <typename Real>
auto FitCameraSamplers(const SegmentQuery<Real>& q) {
  return detail::FitEach(q, static_cast<SegmentSamplers*>(nullptr));
}
template <typename Real>
using CameraSamplerTuple = decltype(FitCameraSamplers(SegmentQuery<Real>{}));
inline constexpr int kCameraSamplerCount = int(SegmentSamplers::kCount);

}  // namespace vrlis::study
