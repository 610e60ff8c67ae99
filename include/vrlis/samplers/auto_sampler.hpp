#pragma once
// `auto`: no more model than a query pays for. Per query it picks equiangular sampling
// (Kulla and Fajardo 2012), Novák's phase fit (Novák et al. 2012) or the FullProduct fit,
// whichever minimises the predicted (1 + relative variance) x cost of one gather
// (docs/maths.md#auto). The prediction needs no fitted target: a few lobe values and two
// distances, and most queries are decided before any lobe is evaluated.
//
// The predictor: for a target f with m <= f <= M, sampling any density p gives a weight
// f / p whose relative variance is at most (rho - 1)^2 / (4 rho), rho = max / min of f / p
// (Kantorovich's inequality). For equiangular sampling f / p is the whole target, phases x
// transmittance; for Novák's fit it is the transmittance (which the fit leaves out) times the
// fit's own residual; for FullProduct the residual alone. The factors' extremes are exact and
// cheap: the segment lobe is monotone in theta (its cosine is -sin theta), the point lobe is
// extreme at the interval's ends or at its peak or antipode when inside, and the
// transmittance falls monotonically from tmin to tmax.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

#include "../effort/lanes_work.hpp"
#include "equiangular.hpp"
#include "full_product.hpp"
#include "novak.hpp"
#include "vrl_point.hpp"

namespace vrlis {

// The ratio max / min of the segment lobe over the query's angle interval: it is monotone in
// theta, so extreme at the ends.
template <typename Real>
Real SegmentLobeRangeRatio(const AngleDomain<Real>& dom, const PhaseProduct<Real>& phase) {
  Real s0 = phase.segment_lobe(0), s1 = phase.segment_lobe(dom.width());
  return std::max(s0, s1) / std::min(s0, s1);
}

// The ratio max / min of the point lobe over the interval: extreme at the ends or at its peak
// or antipode when inside; infinity when it vanishes there (a clamped cosine).
template <typename Real>
Real PointLobeRangeRatio(const AngleDomain<Real>& dom, const PhaseProduct<Real>& phase) {
  if (phase.point_lobe_flat()) return 1;
  Real w = dom.width();
  Real p0 = phase.point_lobe(0), p1 = phase.point_lobe(w), hi = std::max(p0, p1), lo = std::min(p0, p1);
  Real peak = phase.point_peak();  // the peak (or, for g < 0, the backward peak) nearest the interval
  for (Real x : {peak, peak - kPi<Real>, peak + kPi<Real>})
    if (x > 0 && x < w) {
      Real v = phase.point_lobe(x);
      hi = std::max(hi, v);
      lo = std::min(lo, v);
    }
  return hi / lo;
}

// An upper bound of the ratio max / min of the phase product over the interval; infinity
// when a lobe can vanish in it.
template <typename Real>
Real PhaseRangeRatio(const AngleDomain<Real>& dom, const PhaseProduct<Real>& phase) {
  Real ratio = SegmentLobeRangeRatio(dom, phase) * PointLobeRangeRatio(dom, phase);
  return ratio > 0 ? ratio : std::numeric_limits<Real>::infinity();  // NaN (0 / 0) too
}

// For a clamped-cosine point lobe (a diffuse surface), W Int c^2 / (Int c)^2 over the
// interval of width W, in closed form: c = max(cos phi, 0), phi = delta - theta_e, and the
// interval (at most pi wide) meets at most one window |phi - 2 pi k| < pi / 2. Infinity
// when the lobe is zero over the whole interval.
template <typename Real>
double ClampedCosineSecondMoment(const AngleDomain<Real>& dom, const PhaseProduct<Real>& phase) {
  double w = double(dom.width()), a = -double(phase.theta_e_offset()), i1 = 0, i2 = 0;
  const double pi = 3.14159265358979323846;
  for (int k = -1; k <= 1; ++k) {
    double lo = std::max(a, 2 * pi * k - pi / 2), hi = std::min(a + w, 2 * pi * k + pi / 2);
    if (!(hi > lo)) continue;
    // By the sum-to-product formulas about the window's middle m and half width d: no
    // difference of nearly equal sines on a narrow window, and one sine and cosine of each
    // (libm's sincos) instead of four sines.
    const double m = (hi + lo) / 2 - 2 * pi * k, d = (hi - lo) / 2;
    const double sin_m = std::sin(m), cos_m = std::cos(m), sin_d = std::sin(d), cos_d = std::cos(d);
    i1 += 2 * cos_m * sin_d;                                     // sin(hi) - sin(lo)
    i2 += d + (cos_m - sin_m) * (cos_m + sin_m) * sin_d * cos_d;  // (hi - lo) / 2 + (sin 2hi - sin 2lo) / 4
  }
  return i1 > 0 ? w * i2 / (i1 * i1) : std::numeric_limits<double>::infinity();
}

// How much longer the way through the medium to `point` is from tmax than from tmin, along
// the bounded segment origin + t dir and on to the point (at least 0). kLanes: for a loop over
// a batch's queries (lane_math.hpp).
template <bool kLanes = false, typename Real>
Real DepthGrowth(Vec3<Real> point, Vec3<Real> origin, Vec3<Real> dir, Real tmin, Real tmax) {
  const Vec3<Real> far = point - (origin + tmax * dir), near = point - (origin + tmin * dir);
  return std::max((tmax - tmin) + PickSqrt<kLanes>(Dot(far, far)) - PickSqrt<kLanes>(Dot(near, near)), Real(0));
}

// The ratio of the transmittance (along the segment and on to p) between tmin and tmax:
// exp(sigma_t x the growth of the optical depth); infinity on an unbounded segment.
template <typename Real>
Real TransmittanceRangeRatio(const SegmentQuery<Real>& q) {
  if (!(q.sigma_t > 0)) return 1;
  if (!std::isfinite(q.tmax)) return std::numeric_limits<Real>::infinity();
  return std::exp(q.sigma_t * DepthGrowth(q.point, q.origin, q.dir, q.tmin, q.tmax));
}

// For a bounded segment and a clamped-cosine point lobe (a diffuse surface point), an upper
// bound of the phase product's ratio over the interval from both lobes at the segment's ends,
// without the angle domain: the segment lobe is monotone in theta, so its ratio is that of its
// end values; the cosine, where positive at both ends, is concave between them (the interval
// is at most pi wide), so its minimum is at an end and its maximum at most 1. Infinite where
// the cosine is not positive at both ends. The margin covers the rounding of these values
// against the angle domain's (the early-out it feeds must never change a decision).
template <typename Real>
double ClampedCosineEndsRatioBound(const SegmentQuery<Real>& q) {
  double base[2], cosine[2];  // HenyeyGreensteinBase of the segment lobe, and the cosine
  const double g = double(q.g);
  for (int k = 0; k < 2; ++k) {
    const Vec3<Real> to_point = q.point - (q.origin + (k ? q.tmax : q.tmin) * q.dir);
    const double inv_length = 1 / std::sqrt(double(Dot(to_point, to_point)));
    base[k] = 1 + g * g - 2 * g * double(Dot(q.dir, to_point)) * inv_length;
    cosine[k] = -double(Dot(q.lobe.axis, to_point)) * inv_length;
  }
  const double low = std::min(cosine[0], cosine[1]);
  if (!(low > 0)) return std::numeric_limits<double>::infinity();
  const double lobes = std::max(base[0], base[1]) / std::min(base[0], base[1]);  // (max / min of HG)^(2/3)
  return lobes * std::sqrt(lobes) / low * (1 + 1e-3);
}

// An upper bound of the ratio max / min of the whole target (phases x transmittance).
template <typename Real>
Real TargetRangeRatio(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom, const PhaseProduct<Real>& phase) {
  return PhaseRangeRatio(dom, phase) * TransmittanceRangeRatio(q);
}

// The largest ratio a Henyey-Greenstein lobe reaches over all angles, ((1 + |g|) / (1 - |g|))^3:
// a bound of a lobe's ratio on any interval that needs no geometry at all.
template <typename Real>
Real LobeRangeRatioBound(Real g) {
  Real a = std::abs(g);
  Real r = (1 + a) / (1 - a);
  return a < 1 ? r * r * r : std::numeric_limits<Real>::infinity();
}

// Kantorovich's bound on the relative variance of a weight whose max / min ratio is rho.
// kLanes: branch-free, for a loop over a batch's queries (lane_math.hpp).
template <bool kLanes = false, typename Real>
Real UniformVarianceBound(Real rho) {
  constexpr Real kInf = std::numeric_limits<Real>::infinity();
  return Pick<kLanes>(rho < kInf, Sqr(rho - 1) / (4 * rho), kInf);
}

// 1 - z e^z E1(z) for z > 0 (Abramowitz and Stegun 5.1.53 below one, 5.1.56 above, both
// within 5e-5): it falls from 1 at 0 like 1 / z at infinity. kLanes: both computed and
// picked, for a loop over a batch's queries; in float log z is Log1pLanes(z - 1), whose
// rounding of z - 1 (an ulp of 1) the product with z makes negligible.
template <bool kLanes = false, typename T>
[[gnu::always_inline]] inline T ExponentialIntegralComplement(T z) {
  auto small = [z] {
    const T log_z = kLanes ? Log1pLanes(z - 1) : std::log(z);
    const T e1 = -log_z - T(0.57721566) +
                 z * (T(0.99999193) + z * (T(-0.24991055) + z * (T(0.05519968) + z * (T(-0.00976004) + z * T(0.00107857)))));
    return 1 - z * (kLanes ? ExpLanes(z) : std::exp(z)) * e1;
  };
  // (Over z in numerator and denominator: no z^2 to overflow a float.)
  auto large = [z] { return (T(0.995924) + T(1.430913) / z) / (z + T(3.330657) + T(1.681534) / z); };
  if constexpr (kLanes) {
    return SelectLanes(z < 1, small(), large());
  } else {
    return z < 1 ? small() : large();
  }
}

// The transmittance's own second moment under equiangular sampling, W Int T^2 / (Int T)^2
// over the angle interval of width W, on an unbounded segment (where its ratio is infinite),
// from the angle domain's h and W.
// With the half-angle u = pi/2 - chi/2 and tan(chi/2) = cot u ~ 1/u, the optical depth is
// sigma_t h (1/u - 1/U) on u in (0, U], U = W / 2, and Int_0^U e^(-c (1/u - 1/U)) du =
// U (1 - z e^z E1(z)), z = c / U: the moment is C(2z) / C(z)^2 with z = 2 sigma_t h / W
// (docs/maths.md#auto). A prediction (cot u < 1/u puts it a little low where z is large), not a
// bound. kLanes: branch-free (AutoAngle::ChooseLanes).
template <bool kLanes = false, typename T>
[[gnu::always_inline]] inline T UnboundedTransmittanceMoment(T sigma_t, T h, T width) {
  constexpr T kInf = std::numeric_limits<T>::infinity();
  const T z = 2 * sigma_t * h / width;
  if constexpr (!kLanes) {
    if (!(z > 0)) return 1;
    if (!std::isfinite(z)) return kInf;
  }
  const T moment = ExponentialIntegralComplement<kLanes>(2 * z) / Sqr(ExponentialIntegralComplement<kLanes>(z));
  const T at_least_one = Pick<kLanes>(moment > 1, moment, T(1));  // (NaN: 1, as std::max(1, NaN))
  return Pick<kLanes>(!(z > 0), T(1), Pick<kLanes>(z < kInf, at_least_one, kInf));
}
template <typename Real>
double UnboundedTransmittanceMoment(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom) {
  return UnboundedTransmittanceMoment(double(q.sigma_t), double(dom.h()), double(dom.width()));
}

// The transmittance's factor in the models' second moments: Kantorovich's 1 + B(rho_T) on a
// bounded segment (`ratio` is rho_T, TransmittanceRangeRatio, which the rule has already),
// the moment above on an unbounded one.
template <typename Real>
double TransmittanceMoment(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom, double ratio) {
  if (std::isfinite(q.tmax) || !(q.sigma_t > 0)) return 1 + UniformVarianceBound(ratio);
  return UnboundedTransmittanceMoment(q, dom);
}

// The models `auto` chooses from, cheapest first.
enum class AutoModel { Equiangular, Novak, FullProduct };

// The models' costs of one gather sample relative to equiangular's: the counted work of the
// batched gathers on the lanes in use (effort/work_costs.hpp, the effort control's prices), of
// the medium gathers' or of the surface gathers' (whose fits run one query at a time and cost
// more against equiangular's sample; a surface point's lobe is a clamped cosine).
struct AutoCosts {
  double novak, full_product;

  static constexpr AutoCosts Of(const work_costs::LaneWork& lanes, bool surface) {
    auto cost = [&](std::string_view name) {
      const work_costs::SamplerWork w = detail::SamplerWorkOf(lanes, name);
      return surface ? w.surface : w.medium;
    };
    const double equiangular = cost(EquiangularEntry::kName);
    return {cost(NovakEntry::kName) / equiangular, cost(FullProductEntry::kName) / equiangular};
  }
  // Of the gathers at a point whose lobe is `kind` (a clamped cosine: the surface gathers').
  static AutoCosts InUse(LobeKind kind) {
    static constexpr AutoCosts kTable[2][2] = {{Of(work_costs::kBuilt, false), Of(work_costs::kBuilt, true)},
                                               {Of(work_costs::kAvx2, false), Of(work_costs::kAvx2, true)}};
    return kTable[detail::Avx2LanesInUse()][kind == LobeKind::ClampedCosine];
  }
};

// What auto's rule assumes (docs/maths.md#auto).
struct AutoRule {
  // The relative variance a piecewise-linear fit leaves on the part of the target it models:
  // FullProduct's camera-step median relative variance is at most 0.07 at every g of the
  // synthetic map (docs/bench.md); Novák's fit of the phases alone is as close.
  static constexpr double kFitResidual = 0.05;

  // Predicted (1 + relative variance) x cost of each model, from equiangular's predicted
  // second moment W Int f^2 / (Int f)^2 and the transmittance's (TransmittanceMoment). In
  // double one query at a time, in the batch's Real in lanes (AutoAngle::ChooseLanes).
  template <typename T>
  static std::array<T, 3> Scores(T equiangular_moment, T transmittance_moment, const AutoCosts& costs) {
    const T fit = 1 + T(kFitResidual);
    return {equiangular_moment, transmittance_moment * fit * T(costs.novak), fit * T(costs.full_product)};
  }
  // Ties keep the cheaper model. kLanes (here and below): branch-free, as in ChooseLanes.
  template <bool kLanes = false, typename T>
  static AutoModel Cheapest(const std::array<T, 3>& score) {
    const bool novak = score[1] < score[0], full = score[2] < Pick<kLanes>(novak, score[1], score[0]);
    return AutoModel(2 * int(full) + int(novak & !full));
  }
  // A bound of equiangular's second moment from a bound `phases` of the phase product's ratio
  // and the transmittance's ratio and moment: Kantorovich's on the whole target, or the
  // transmittance's moment times phases^2 (f <= max(phases) T, f >= min(phases) T), which
  // stays finite on an unbounded segment.
  template <bool kLanes = false, typename T>
  static T MomentBound(T phases, T transmittance_ratio, T transmittance_moment) {
    return std::min(1 + UniformVarianceBound<kLanes>(phases * transmittance_ratio), Sqr(phases) * transmittance_moment);
  }
  // The early-outs, which look at no lobe and never change a decision. Every prediction of
  // equiangular's second moment is at least the transmittance's moment, so FullProduct wins
  // whenever it beats that floor and Novák (whose score depends on that moment alone).
  template <bool kLanes = false, typename T>
  static bool FullProductSuffices(T transmittance_moment, const AutoCosts& costs) {
    return Cheapest<kLanes>(Scores(transmittance_moment, transmittance_moment, costs)) == AutoModel::FullProduct;
  }
  // Equiangular wins whenever a bound of its moment from any bound of the phases' ratio is no
  // more than the cheapest fit's best case (relative variance 0 at Novák's cost).
  template <bool kLanes = false, typename T>
  static bool EquiangularSuffices(T phases, T transmittance_ratio, T transmittance_moment, const AutoCosts& costs) {
    return MomentBound<kLanes>(phases, transmittance_ratio, transmittance_moment) <= T(costs.novak);
  }

  // Equiangular's predicted second moment: MomentBound with the phases' exact ratio; for a
  // clamped-cosine point lobe also the cosine's exact moment times the squared ratios of the
  // other factors (f <= max(others) c and f >= min(others) c), which stays finite where the
  // cosine vanishes inside the interval. The smallest of these.
  template <typename Real>
  static double EquiangularMoment(const AngleDomain<Real>& dom, const PhaseProduct<Real>& phase,
                                  double transmittance_ratio, double transmittance_moment) {
    double segment = double(SegmentLobeRangeRatio(dom, phase));
    double moment = MomentBound(double(PhaseRangeRatio(dom, phase)), transmittance_ratio, transmittance_moment);
    if (phase.point_kind() == LobeKind::ClampedCosine)
      moment = std::min(moment, Sqr(segment * transmittance_ratio) * ClampedCosineSecondMoment(dom, phase));
    return moment;
  }
};

template <typename R>
class AutoAngle {
 public:
  using Real = R;
  // The fits are the registered samplers' own (Novák: 10 nodes, FullProduct: 8).
  using NovakFit = std::remove_cv_t<std::remove_reference_t<decltype(std::declval<Novak<Real>>().distribution())>>;
  using FullFit = std::remove_cv_t<std::remove_reference_t<decltype(std::declval<FullProduct<Real>>().distribution())>>;

  AutoAngle(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom) : dist_(Make(q, dom)) {}

  // The rule: first the two early-outs, which need no lobe evaluated, then the exact ratios;
  // *phase receives the phase product built for them (the one Novák's fit uses), if any.
  static AutoModel Choose(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom,
                          std::optional<PhaseProduct<Real>>* phase = nullptr) {
    double ratio = double(TransmittanceRangeRatio(q)), moment = TransmittanceMoment(q, dom, ratio);
    const AutoCosts costs = AutoCosts::InUse(q.lobe.kind);
    // The early-outs exclude each other (every bound of equiangular's moment is at least the
    // transmittance's, and Novák costs no more than FullProduct, as the equiangular one
    // assumes): the one that looks at no lobe goes first.
    if (AutoRule::FullProductSuffices(moment, costs)) return AutoModel::FullProduct;
    double point = q.lobe.kind == LobeKind::HenyeyGreenstein ? double(LobeRangeRatioBound(q.lobe.g))
                   : q.lobe.kind == LobeKind::None          ? 1.0
                                                            : std::numeric_limits<double>::infinity();
    // At a surface point the lobes' end values bound the phases far closer than the lobes'
    // largest ratios do, and decide most of the surface gathers' queries without a lobe angle.
    const double phases = q.lobe.kind == LobeKind::ClampedCosine && std::isfinite(q.tmax)
                              ? ClampedCosineEndsRatioBound(q)
                              : double(LobeRangeRatioBound(q.g)) * point;
    if (AutoRule::EquiangularSuffices(phases, ratio, moment, costs)) return AutoModel::Equiangular;
    std::optional<PhaseProduct<Real>> own;
    const PhaseProduct<Real>& built = (phase ? *phase : own).emplace(q, dom);
    return AutoRule::Cheapest(AutoRule::Scores(AutoRule::EquiangularMoment(dom, built, ratio, moment), moment, costs));
  }

  // Choose for a batch of the medium gathers' queries in vector lanes (their point lobe a
  // Henyey-Greenstein lobe with the segment's g), from their angle frames, VRL directions
  // (axis_*) and, on a bounded segment, DepthGrowth (depth; null on an unbounded one).
  // First the early-outs in every lane; the lanes they leave (none where the transmittance
  // alone asks for FullProduct, say) take the whole rule (WholeRule) on their phase products,
  // gathered into lanes of their own unless they are all of them. The same decisions as
  // Choose but where rounding parts two scores that tie.
  template <int kSize>
  static void ChooseLanes(const detail::AngleFrameLanes<Real, kSize>& frames, const Real* axis_x, const Real* axis_y,
                          const Real* axis_z, Vec3<Real> dir, Real g, Real sigma_t, const Real* depth, int lanes,
                          AutoModel* models) {
    constexpr Real kInf = std::numeric_limits<Real>::infinity();
    const Real phases_bound = Sqr(LobeRangeRatioBound(g));
    const AutoCosts costs = AutoCosts::InUse(LobeKind::HenyeyGreenstein);
    Real ratio[kSize], moment[kSize];
    if (depth) {
      for (int i = 0; i < lanes; ++i)
        ratio[i] = ExpLanes(sigma_t * depth[i]), moment[i] = 1 + UniformVarianceBound<true>(ratio[i]);
    } else {
      for (int i = 0; i < lanes; ++i)
        ratio[i] = sigma_t > 0 ? kInf : Real(1),
        moment[i] = UnboundedTransmittanceMoment<true>(sigma_t, frames.h[i], frames.width[i]);
    }
    int undecided = 0, index[kSize];  // the lanes the early-outs leave, in order
    for (int i = 0; i < lanes; ++i) {
      const bool equiangular = AutoRule::EquiangularSuffices<true>(phases_bound, ratio[i], moment[i], costs);
      const bool full = AutoRule::FullProductSuffices<true>(moment[i], costs);
      models[i] = AutoModel(2 * int(full & !equiangular));
      index[undecided] = i;
      undecided += int(!equiangular & !full);
    }
    if (undecided == 0) return;
    if (undecided == lanes) return WholeRule(frames, axis_x, axis_y, axis_z, dir, g, ratio, moment, lanes, costs, models);
    // The others, gathered into lanes of their own (the unused ones repeat the first).
    const int whole = detail::WholeLanes(undecided);
    detail::AngleFrameLanes<Real, kSize> gathered;
    Real x[kSize], y[kSize], z[kSize], gathered_ratio[kSize], gathered_moment[kSize];
    for (int j = 0; j < whole; ++j) {
      const int i = index[j < undecided ? j : 0];
      gathered.set(j, frames[i]);
      x[j] = axis_x[i], y[j] = axis_y[i], z[j] = axis_z[i], gathered_ratio[j] = ratio[i], gathered_moment[j] = moment[i];
    }
    AutoModel decided[kSize];
    WholeRule(gathered, x, y, z, dir, g, gathered_ratio, gathered_moment, whole, costs, decided);
    for (int j = 0; j < undecided; ++j) models[index[j]] = decided[j];
  }

  // ChooseLanes' whole rule on every lane of a batch, from the lanes' transmittance ratios
  // and moments: the phases' ratio from the lobes at the interval's ends and, where inside
  // it, at the point lobe's peak and antipode values, which need no angle.
  template <int kSize>
  static void WholeRule(const detail::AngleFrameLanes<Real, kSize>& frames, const Real* axis_x, const Real* axis_y,
                        const Real* axis_z, Vec3<Real> dir, Real g, const Real* ratio, const Real* moment, int lanes,
                        const AutoCosts& costs, AutoModel* models) {
    constexpr Real kInf = std::numeric_limits<Real>::infinity();
    typename PhaseProduct<Real>::template Lanes<kSize, false> phase;
    phase.template build<Accuracy::Full>(frames, axis_x, axis_y, axis_z, dir, g, Real(0), lanes);
    for (int i = 0; i < lanes; ++i) {
      const Real width = phase.width[i], r = phase.r[i], one_minus_r = phase.one_minus_r[i];
      auto segment = [&](Real delta) {  // PhaseProduct::segment_lobe
        const SinCosPair<Real> half = SinCosLanes((delta - phase.lower[i]) / 2);
        return HenyeyGreenstein<true>(g, 2 * Sqr(half.sin), 2 * Sqr(half.cos));
      };
      auto point = [&](Real s2) {  // PhaseProduct::point_lobe, s2 the squared sine of half its angle
        return HenyeyGreenstein<true>(g, one_minus_r + 2 * r * s2, one_minus_r + 2 * r * (1 - s2));
      };
      const Real s0 = segment(0), s1 = segment(width);
      const Real p0 = point(Sqr(SinCosLanes(-phase.theta_e[i] / 2).sin));
      const Real p1 = point(Sqr(SinCosLanes((width - phase.theta_e[i]) / 2).sin));
      const Real peak = phase.point_peak(i), below = peak - kPi<Real>, above = peak + kPi<Real>;
      const Real hi = SelectLanes((peak > 0) & (peak < width), point(g >= 0 ? Real(0) : Real(1)), std::max(p0, p1));
      const Real lo = SelectLanes(((below > 0) & (below < width)) | ((above > 0) & (above < width)),
                                  point(g >= 0 ? Real(1) : Real(0)), std::min(p0, p1));
      const Real phases = std::max(s0, s1) / std::min(s0, s1) * (hi / lo);
      models[i] = AutoRule::Cheapest<true>(AutoRule::Scores(
          AutoRule::MomentBound<true>(SelectLanes(phases > 0, phases, kInf), ratio[i], moment[i]), moment[i], costs));
    }
  }

  // A batch's camera steps in vector lanes (the medium gathers', as the fits' SampleLanes):
  // lane i took models[i] (Choose or ChooseLanes); each fitted model's lanes are gathered into
  // a batch of their own (unless they are all of them) and fitted and sampled in lanes. out[i]
  // is sample_pdf(u[i]) of lane i's query, to rounding.
  template <int kSize>
  static void SampleLanes(const AutoModel* models, const detail::AngleFrameLanes<Real, kSize>& frames,
                          const Real* axis_x, const Real* axis_y, const Real* axis_z, Vec3<Real> dir, Real g,
                          Real sigma_t, const Real* u, int lanes, SegmentSample<Real>* out) {
    int novak = 0, full = 0;  // how many lanes took each fit (counted branch-free)
    for (int i = 0; i < lanes; ++i)
      novak += int(models[i] == AutoModel::Novak), full += int(models[i] == AutoModel::FullProduct);
    if (novak + full < lanes)
      for (int i = 0; i < lanes; ++i)
        if (models[i] == AutoModel::Equiangular) out[i] = UniformAngle<Real>(frames.width[i]).sample_pdf(u[i]);
    const ModelLanes<kSize> batch{models, frames, axis_x, axis_y, axis_z, dir, g, sigma_t, u, lanes};
    batch.template Sample<NovakFit>(AutoModel::Novak, novak, out);
    batch.template Sample<FullFit>(AutoModel::FullProduct, full, out);
  }

  AutoModel model() const { return AutoModel(dist_.index()); }
  Real sample(Real u) const { return std::visit([&](const auto& d) { return d.sample(u); }, dist_); }
  Real pdf(Real delta) const { return std::visit([&](const auto& d) { return d.pdf(delta); }, dist_); }
  Real cdf(Real delta) const { return std::visit([&](const auto& d) { return d.cdf(delta); }, dist_); }
  SegmentSample<Real> sample_pdf(Real u) const {
    return std::visit([&](const auto& d) { return d.sample_pdf(u); }, dist_);
  }

 private:
  using Dist = std::variant<UniformAngle<Real>, NovakFit, FullFit>;  // in AutoModel's order

  static Dist Make(const SegmentQuery<Real>& q, const AngleDomain<Real>& dom) {
    std::optional<PhaseProduct<Real>> phase;
    switch (Choose(q, dom, &phase)) {
      case AutoModel::Novak: return Dist(std::in_place_index<1>, *phase, dom.width());
      case AutoModel::FullProduct:
        if (phase) return Dist(std::in_place_index<2>, FullProductTarget<Real>(*phase, q, dom), dom.width());
        return Dist(std::in_place_index<2>, q, dom);
      case AutoModel::Equiangular: break;
    }
    return Dist(std::in_place_index<0>, q, dom);
  }

  // The lanes of a batch (SampleLanes) and what their fits are built from.
  template <int kSize>
  struct ModelLanes {
    const AutoModel* models;
    const detail::AngleFrameLanes<Real, kSize>& frames;
    const Real *axis_x, *axis_y, *axis_z;
    Vec3<Real> dir;
    Real g, sigma_t;
    const Real* u;
    int lanes;

    // The `taken` lanes that took `model`, fitted and sampled by Fit's SampleLanes (the unused lanes
    // of the gathered batch repeat its first); where every lane took it, the batch as it is.
    template <typename Fit>
    void Sample(AutoModel model, int taken, SegmentSample<Real>* out) const {
      auto fit = [&](const detail::AngleFrameLanes<Real, kSize>& f, const Real* x, const Real* y, const Real* z,
                     const Real* v, int count, SegmentSample<Real>* d) {
        typename Fit::template TargetLanes<kSize> target;
        target.template build<Accuracy::Fit>(f, x, y, z, dir, g, sigma_t, count);
        Fit::template SampleLanes<kSize>(target, v, count, d);
      };
      if (taken == 0) return;
      if (taken == lanes) return fit(frames, axis_x, axis_y, axis_z, u, lanes, out);
      int index[kSize];
      for (int i = 0, j = 0; i < lanes; ++i)
        if (models[i] == model) index[j++] = i;
      const int whole = detail::WholeLanes(taken);
      detail::AngleFrameLanes<Real, kSize> gathered;
      Real x[kSize], y[kSize], z[kSize], v[kSize];
      for (int j = 0; j < whole; ++j) {
        const int i = index[j < taken ? j : 0];
        gathered.set(j, frames[i]);
        x[j] = axis_x[i], y[j] = axis_y[i], z[j] = axis_z[i], v[j] = u[i];
      }
      SegmentSample<Real> d[kSize];
      fit(gathered, x, y, z, v, whole, d);
      for (int j = 0; j < taken; ++j) out[index[j]] = d[j];
    }
  };

  Dist dist_;
};

template <typename Real = float>
using Auto = SegmentSampler<AutoAngle<Real>>;

// Its entry in the run-time sampler tables (method.hpp).
struct AutoEntry {
  static constexpr std::string_view kName = "auto";
  template <typename Real>
  using Sampler = Auto<Real>;
};

}  // namespace vrlis
