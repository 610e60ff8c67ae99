#pragma once
// Choosing a camera-segment sampler at run time without virtual calls: WithSampler builds
// the chosen sampler and hands it to a generic callable.
#include <array>
#include <optional>
#include <string_view>

#include "samplers/cauchy_mixture.hpp"
#include "samplers/cauchy_sum.hpp"
#include "samplers/equiangular.hpp"
#include "samplers/full_product.hpp"
#include "samplers/novak.hpp"

namespace vrlis {

enum class Method { Equiangular, Novak, CauchySum, CauchyMixture, FullProduct };

inline constexpr std::array<Method, 5> kMethods = {Method::Equiangular, Method::Novak, Method::CauchySum,
                                                   Method::CauchyMixture, Method::FullProduct};

inline constexpr std::string_view Name(Method m) {
  switch (m) {
    case Method::Equiangular: return "equiangular";
    case Method::Novak: return "novak";
    case Method::CauchySum: return "cauchy-sum";
    case Method::CauchyMixture: return "cauchy-mixture";
    case Method::FullProduct: return "full-product";
  }
  return "unknown";
}

inline std::optional<Method> ParseMethod(std::string_view name) {
  for (Method m : kMethods)
    if (Name(m) == name) return m;
  return std::nullopt;
}

template <typename Real, typename F>
decltype(auto) WithSampler(Method m, const SegmentQuery<Real>& q, F&& f) {
  switch (m) {
    case Method::Novak: return f(Novak<Real>(q));
    case Method::CauchySum: return f(CauchySum<Real>(q));
    case Method::CauchyMixture: return f(CauchyMixture<Real>(q));
    case Method::FullProduct: return f(FullProduct<Real>(q));
    case Method::Equiangular: break;
  }
  return f(Equiangular<Real>(q));
}

}  // namespace vrlis
