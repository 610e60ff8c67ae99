#pragma once
// Relative variances of the medium-to-medium estimator by numerical quadrature
// (docs/maths.md): Int f^2 / p / (Int f)^2 - 1, for every camera sampler at once.
//
// Camera step (VRL point y fixed): integrated over the sampler's own angle variable
// delta = theta - theta_a, where du = d delta / J(u), J = dtheta/du, and the sampler's
// density is p(u) = p_theta(delta) J(u):
//   Int f du       = Int (f / J) d delta
//   Int f^2 / p du = Int (f / J)^2 / p_theta d delta.
// f / J = rho rho T T T / h is bounded: the inverse square is gone. The interval is split at
// Novák's nodes (where its density has kinks), at both lobes' peaks and at a few multiples
// of the lobes' widths around them, so g = 0.99 spikes are resolved.
//
// Whole estimator (VRL point by VrlPoint with density p1, then the camera point):
//   E[(f / (p1 p2))^2] = Int dv (1 / p1) Int du f^2 / p2,
// integrated over xi with v = VrlPoint.sample(xi), dv = d xi / p1, where p1 follows the
// inverse distance to the camera line and cancels its singular part.
//
// Everything runs in double (the samplers are instantiated in double; speed is measured
// in float elsewhere).
#include <algorithm>
#include <array>
#include <limits>
#include <tuple>
#include <vector>

#include "quadrature.hpp"
#include "samplers.hpp"

namespace vrlis::study {

struct QuadratureSettings {
  double inner_tol = 1e-7;   // relative, on the pessimistic G7 error
  int inner_max = 40000;     // evaluations
  double outer_tol = 1e-5;
  int outer_max = 4000;      // outer evaluations (each one an inner quadrature)
};

struct Moments {
  double first = 0;                                    // Int f
  std::array<double, kCameraSamplerCount> second{};    // Int f^2 / p, per sampler
  // Int (f - p Int f)^2 / p, per sampler, when computed (central[0] >= 0): the variance
  // without the cancellation of second - first^2, for near-perfect samplers.
  std::array<double, kCameraSamplerCount> central{-1};
  // Whole estimator only: Int f^2 / p with VrlMarginal as step one, per camera sampler.
  std::array<double, kCameraSamplerCount> second_marginal{};
  double rel_error = 0;                                // largest estimated relative error
  int evaluations = 0;                                 // integrand evaluations
  bool converged = true;

  double RelativeVariance(int k) const {
    return central[0] >= 0 ? central[k] / (first * first) : second[k] / (first * first) - 1;
  }
  double RelativeVarianceMarginal(int k) const { return second_marginal[k] / (first * first) - 1; }
};

// The breakpoints of the camera-step quadrature for one query, in delta: the nodes of the
// piecewise-linear samplers (kinks of their densities), both lobes' peaks and a few multiples
// of the lobes' and the thesis's Cauchy widths around them.
inline std::vector<double> CameraBreaks(const SegmentQuery<double>& q, const AngleDomain<double>& dom,
                                        const CameraSamplerTuple<double>& samplers) {
  double width = dom.width();
  std::vector<double> breaks = {0, width};
  for (double node : std::get<Novak<double>>(samplers).distribution().nodes()) breaks.push_back(node);
  for (double node : std::get<FullProduct<double>>(samplers).distribution().nodes()) breaks.push_back(node);
  PhaseProduct<double> target(q, dom);
  double a = std::abs(q.g);
  double cauchy = 4 * (1 - a) * (1 - a) / (1 + a);  // the thesis's Cauchy scale at the segment lobe's peak
  const double offsets[] = {0, cauchy, 4 * cauchy, 1 - a, 4 * (1 - a), 16 * (1 - a)};
  for (double peak : {target.point_peak(), target.segment_peak()})
    for (double o : offsets)
      for (double x : {peak - o, peak + o})
        if (x > 0 && x < width) breaks.push_back(x);
  std::sort(breaks.begin(), breaks.end());
  std::vector<double> kept;
  for (double x : breaks)
    if (kept.empty() || x - kept.back() > 1e-13 * width) kept.push_back(x);
  kept.back() = width;
  return kept;
}

// The integrand at the camera parameter t (zero at an unbounded segment's far end) and the
// VRL parameter v.
inline double IntegrandAt(const MediumGatherQuery<double>& q, double t, double v) {
  return std::isfinite(t) ? MediumGatherIntegrand(q, t, v) : 0.0;
}

// Camera step for the VRL point y = y(v): Int f du and Int f^2 / p du for every sampler;
// with `central`, a second pass integrates (f - p Int f)^2 / p as well.
inline Moments CameraMoments(const MediumGatherQuery<double>& gq, double v, const QuadratureSettings& s = {},
                             bool central = false) {
  constexpr int K = kCameraSamplerCount;
  SegmentQuery<double> q = CameraStepQuery(gq, gq.vrl.at(v));
  CameraSamplerTuple<double> samplers = FitCameraSamplers(q);
  const auto& eq = std::get<0>(samplers);
  const AngleDomain<double>& dom = eq.domain();
  Moments m;
  if (!eq.valid() || !(dom.width() > 0)) return m;
  auto integrand = [&](double delta) {
    double u = dom.t_at(delta);
    double fj = IntegrandAt(gq, u, v) / dom.dtheta_dt(u);
    double f2 = fj * fj;
    std::array<double, K + 1> out{fj};
    std::apply([&](const auto&... sampler) {
      int k = 1;
      ((out[k++] = f2 / sampler.distribution().pdf(delta)), ...);
    }, samplers);
    return out;
  };
  auto r = Integrate<K + 1>(integrand, CameraBreaks(q, dom, samplers), s.inner_tol, s.inner_max);
  m.first = r.value[0];
  for (int k = 0; k < K; ++k) m.second[k] = r.value[k + 1];
  for (int n = 0; n <= K; ++n) m.rel_error = std::max(m.rel_error, r.error[n] / std::abs(r.value[n]));
  m.evaluations = r.evaluations;
  m.converged = r.converged;
  if (!central) return m;
  double F = m.first;
  auto deviation = [&](double delta) {
    double u = dom.t_at(delta);
    double fj = IntegrandAt(gq, u, v) / dom.dtheta_dt(u);
    std::array<double, K> out{};
    std::apply([&](const auto&... sampler) {
      int k = 0;
      ((out[k++] = [&](double pdf) { return (fj - F * pdf) * (fj - F * pdf) / pdf; }(sampler.distribution().pdf(delta))),
       ...);
    }, samplers);
    return out;
  };
  // Absolute floor: variances below 1e-14 F^2 are zero for our purposes.
  auto c = Integrate<K>(deviation, CameraBreaks(q, dom, samplers), s.inner_tol, s.inner_max, 1e-14 * F * F);
  m.central = c.value;
  m.evaluations += c.evaluations;
  m.converged = m.converged && c.converged;
  return m;
}

// The camera step alone, at the configuration's fixed VRL point VrlPoint.sample(xi_vrl).
inline Moments CameraStepMoments(const MediumGatherQuery<double>& q, double xi_vrl, const QuadratureSettings& s = {}) {
  VrlPoint<double> vp(q);
  return CameraMoments(q, vp.sample(xi_vrl), s, true);
}

// The whole two-step estimator f(u, v) / (p1(v) p2(u | v)), with VrlPoint as step one and
// with VrlMarginal (density pm(v)) as step one:
//   E[(f / (pm p2))^2] = Int dv (1 / pm) Int du f^2 / p2 = Int dxi (1 / (p1 pm)) Int du f^2 / p2,
// on the same outer variable xi (VrlPoint's), broken at VrlMarginal's nodes (its kinks).
// VrlMarginal needs a finite camera segment: for an unbounded one second_marginal is NaN.
// fitted_for: VrlMarginal's fit over xi made for this query instead (the same VRL seen from a
// neighbouring camera segment), warped by q's own VrlPoint, pm(v) = p1(v) PL(P1(v)): still a
// density on the VRL, so the estimator stays unbiased; what sharing one fit between
// neighbouring pixels would cost (docs/maths.md#vrl-marginal-shared).
inline Moments WholeMoments(const MediumGatherQuery<double>& q, const QuadratureSettings& s = {},
                            const MediumGatherQuery<double>* fitted_for = nullptr) {
  constexpr int K = kCameraSamplerCount;
  VrlPoint<double> vp(q);
  VrlMarginal<double> vm(fitted_for ? *fitted_for : q);
  Moments m;
  int inner_evaluations = 0;
  bool inner_converged = true;
  double inner_error = 0;
  auto integrand = [&](double xi) {
    double v = vp.sample(xi), p1 = vp.pdf(v);
    Moments c = CameraMoments(q, v, s);
    inner_evaluations += c.evaluations;
    inner_converged = inner_converged && c.converged;
    inner_error = std::max(inner_error, c.rel_error);
    double pm = vm.valid() ? p1 * vm.xi_density(vp.invert(v)) : p1;  // (a placeholder, replaced by NaN below)
    std::array<double, 2 * K + 1> out{c.first / p1};
    for (int k = 0; k < K; ++k) {
      out[k + 1] = c.second[k] / (p1 * p1);
      out[K + k + 1] = c.second[k] / (p1 * pm);
    }
    return out;
  };
  // Eight even pieces plus the VRL parameter closest to the camera line: Novák's node layout
  // jumps with v, so the outer integrand has steps that the adaptivity must find.
  std::vector<double> breaks;
  for (int i = 0; i <= 8; ++i) breaks.push_back(i / 8.0);
  for (int j = 0; j < VrlMarginal<double>::kNodeCount; ++j) breaks.push_back(VrlMarginal<double>::node(j));
  Vec3<double> wl = q.vrl.dir, wc = q.camera.dir, c = Cross(wl, wc);
  double sin2 = Dot(c, c);
  if (sin2 > 1e-12) {
    Vec3<double> d = q.camera.origin - q.vrl.origin;
    double v0 = (Dot(d, wl) - Dot(d, wc) * Dot(wl, wc)) / sin2;
    if (v0 > 0 && v0 < q.vrl.length) breaks.push_back(vp.invert(v0));
  }
  auto r = Integrate<2 * K + 1>(integrand, breaks, s.outer_tol, s.outer_max);
  m.first = r.value[0];
  for (int k = 0; k < K; ++k) {
    m.second[k] = r.value[k + 1];
    m.second_marginal[k] = vm.valid() ? r.value[K + k + 1] : std::numeric_limits<double>::quiet_NaN();
  }
  for (int n = 0; n <= 2 * K; ++n) m.rel_error = std::max(m.rel_error, r.error[n] / std::abs(r.value[n]));
  m.rel_error = std::max(m.rel_error, inner_error);
  m.evaluations = inner_evaluations;
  m.converged = r.converged && inner_converged;
  return m;
}

}  // namespace vrlis::study
