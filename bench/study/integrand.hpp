#pragma once
// The medium-to-medium integrand without visibility (section 1 of the maths note):
//   f(u, v) = rho(wc . w^) rho(-wl . w^) T(u) T(v) T(|w|) / |w|^2,  w = y(v) - x(u),
// with T(d) = exp(-sigma_t d). The constant Phi sigma_s^2 is left out: it cancels in every
// relative variance.
#include <tuple>

#include "config.hpp"

namespace vrlis::study {

namespace detail {
// HG(g, a . b) for unit a, b, with 1 -+ cos = |b -+ a|^2 / 2: exact near both peaks.
template <typename Real>
Real HgBetween(Real g, Vec3<Real> a, Vec3<Real> b) {
  Vec3<Real> dm = b - a, dp = b + a;
  return HenyeyGreenstein(g, Dot(dm, dm) / 2, Dot(dp, dp) / 2);
}
}  // namespace detail

// f at the camera point x(u) and the VRL point y = y(v).
template <typename Real>
Real IntegrandAt(const Pair<Real>& p, Real u, Vec3<Real> y, Real v) {
  Vec3<Real> w = y - (p.xc + u * p.wc);
  Real d2 = Dot(w, w), d = std::sqrt(d2);
  Vec3<Real> wh = (Real(1) / d) * w;
  Real phase = detail::HgBetween(p.g, p.wc, wh) * detail::HgBetween(p.g, -p.wl, wh);
  return phase * std::exp(-p.sigma_t * (u + v + d)) / d2;
}

template <typename Real>
Real Integrand(const Pair<Real>& p, Real u, Real v) { return IntegrandAt(p, u, VrlPointAt(p, v), v); }

// The camera samplers, in the order every study reports them. FullProduct is vrlis's own
// (Novák's construction over phases x transmittance, 16 nodes); the others are published.
template <typename Real>
using SamplerTuple =
    std::tuple<Equiangular<Real>, Novak<Real>, CauchySum<Real>, CauchyMixture<Real>, FullProduct<Real>>;
inline constexpr int kCameraSamplerCount = int(std::tuple_size_v<SamplerTuple<float>>);
inline constexpr const char* kCameraSamplerNames[kCameraSamplerCount] = {"Equiangular", "Novak", "CauchySum",
                                                                          "CauchyMixture", "FullProduct"};

}  // namespace vrlis::study
