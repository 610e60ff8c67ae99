#pragma once
// Adapter for a renderer's own vector type: any type with members x, y and z converts to
// vrlis's Vec3 and back, so that no renderer writes its own converters (glm.hpp is the same
// for GLM, with query builders on top).
#include <type_traits>
#include <utility>

#include "core/vec3.hpp"

namespace vrlis {

template <typename V, typename = void>
struct HasXyz : std::false_type {};
template <typename V>
struct HasXyz<V, std::void_t<decltype(std::declval<const V&>().x), decltype(std::declval<const V&>().y),
                             decltype(std::declval<const V&>().z)>> : std::true_type {};

// v as a Vec3<Real>; Real defaults to the type of v.x.
template <typename Real = void, typename V>
auto FromXyz(const V& v) {
  static_assert(HasXyz<V>::value, "vrlis::FromXyz needs a vector type with members x, y and z");
  using R = std::conditional_t<std::is_void_v<Real>, std::decay_t<decltype(v.x)>, Real>;
  return Vec3<R>{R(v.x), R(v.y), R(v.z)};
}

// a as the renderer's V: V(x, y, z) where V has that constructor, else a value-initialised V
// whose x, y and z are assigned (aggregates).
template <typename V, typename Real>
V ToXyz(Vec3<Real> a) {
  static_assert(HasXyz<V>::value, "vrlis::ToXyz needs a vector type with members x, y and z");
  using R = std::decay_t<decltype(std::declval<V&>().x)>;
  if constexpr (std::is_constructible_v<V, R, R, R>) {
    return V(R(a.x), R(a.y), R(a.z));
  } else {
    V v{};
    v.x = R(a.x);
    v.y = R(a.y);
    v.z = R(a.z);
    return v;
  }
}

}  // namespace vrlis
