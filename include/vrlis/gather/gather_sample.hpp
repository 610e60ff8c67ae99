#pragma once
// The outcome of one gather estimate: the sampled points, their densities and the weight
// f / pdf of everything except visibility and the light's power. A renderer traces one
// occlusion ray between camera_point and light_point and multiplies.
#include <limits>

#include "../angle/angle_domain.hpp"
#include "../core/gather_query.hpp"
#include "../core/lane_math.hpp"

namespace vrlis {

// How many gathers a batched call (SampleMediumGathers, SampleSurfaceGathers) runs at once:
// four vectors of eight float lanes, whose chains of dependent operations the processor
// overlaps (one vector at a time is one chain).
inline constexpr int kGatherChunk = 32;

namespace detail {
// The medium's share of a gather's integrand: sigma_s once per scattering event (1 or 2),
// and the transmittance of the light's whole way through the medium. kLanes: for a loop
// over a batch's gathers (lane_math.hpp).
template <bool kLanes = false, typename Real>
[[gnu::always_inline]] inline Real MediumFactor(Real sigma_s, Real sigma_t, int scatterings, Real path_length) {
  return Pick<kLanes>(scatterings == 2, sigma_s * sigma_s, sigma_s) * PickExp<kLanes>(-sigma_t * path_length);
}
}  // namespace detail

template <typename Real>
struct GatherSample {
  Vec3<Real> camera_point{}, light_point{};  // the ends of the occlusion ray
  Real t = 0, pdf_t = 0;  // on the camera segment (medium and point-light gathers)
  Real v = 0, pdf_v = 0;  // on the VRL (medium and surface gathers)
  // exp(-sigma_t |light_point - camera_point|), included in weight. A renderer whose medium
  // does not fill the connection replaces it by its own transmittance (weight / transmittance).
  Real transmittance = 0;
  Real weight = 0;  // 0: nothing to trace
  // The weight's factors, for coefficients that differ per channel (RGB, spectral; g is
  // shared): weight == bare_weight * sigma_s^scatterings * exp(-sigma_t * path_length).
  Real bare_weight = 0;  // the weight at sigma_s = 1, sigma_t = 0; 0: nothing to trace in any channel
  // The light's way through the medium, the legs the gather has: (t - tmin) on the camera
  // segment, v on the VRL, and the connection |light_point - camera_point|.
  Real path_length = 0;
  int scatterings = 0;  // 2 medium to medium; 1 medium to surface and single scattering
  // Where `auto`'s per-query rule chose the step's model (the camera step; at a surface the
  // VRL step): the sample's density over equiangular sampling's at the same point; else 0.
  // E[weight^2 x over_equiangular] over these samples is equiangular sampling's second
  // moment, which a renderer weighs against auto's own (EffortSettings::model).
  Real over_equiangular = 0;
  // The same over CauchyMixture's density, where the call asked (EffortSettings::measure_mixture).
  Real over_mixture = 0;

  bool contributes() const { return weight > 0; }
  // The weight in one channel of the medium, its coefficients built as the query's were (its
  // g must be the query's). The points and pdfs stay those sampled for the query's medium, so
  // the weight is unbiased in every channel.
  template <bool kLanes = false>
  Real weight_for(const Medium<Real>& channel) const {
    return bare_weight * detail::MediumFactor<kLanes>(channel.sigma_s, channel.sigma_t, scatterings, path_length);
  }
};

// A gather's integrand at one sample without visibility, factored as GatherSample's weight:
// f = bare sigma_s^scatterings exp(-sigma_t path_length); connection is |y - x|.
template <typename Real>
struct IntegrandFactors {
  Real bare = 0, path_length = 0, connection = 0;  // bare 0: the integrand vanishes
  int scatterings = 0;

  // The integrand's value in the medium m, and the connection's transmittance if asked.
  Real value(const Medium<Real>& m, Real* transmittance = nullptr) const {
    if (!(bare > 0)) return 0;
    if (transmittance) *transmittance = std::exp(-m.sigma_t * connection);
    return bare * detail::MediumFactor(m.sigma_s, m.sigma_t, scatterings, path_length);
  }
};

namespace detail {
template <bool kLanes = false, typename Real>
Real FiniteOrZero(Real x) { return Pick<kLanes>((x > 0) & (x < std::numeric_limits<Real>::infinity()), x, Real(0)); }

// GatherSample::over_equiangular of the sample s drawn on `domain` (its sampler's):
// equiangular sampling's density is uniform in the angle, 1 / width.
template <typename Real>
Real OverEquiangular(const AngleDomain<Real>& domain, SegmentSample<Real> s) {
  const Real uniform = domain.dtheta_dt(s.t) / domain.width();
  return FiniteOrZero(s.pdf / uniform);
}

// The same over the density of `Other` (an angle distribution) fitted to the query q on its
// domain: the two share the angle's Jacobian.
template <typename Other, typename Real>
Real OverDensity(const AngleDomain<Real>& domain, const SegmentQuery<Real>& q, SegmentSample<Real> s) {
  return FiniteOrZero(s.pdf / (Other(q, domain).pdf(domain.offset_at(s.t)) * domain.dtheta_dt(s.t)));
}

template <typename Real>
bool Usable(SegmentSample<Real> s) {
  constexpr Real kInf = std::numeric_limits<Real>::infinity();
  return (s.pdf > 0) & (s.pdf < kInf) & (std::abs(s.t) < kInf);  // no branches: it runs in lanes too
}

// Fills s's connection and weights from the integrand's factors and the pdf; any non-finite
// or non-positive outcome becomes "nothing to trace" (never a NaN in an image). kLanes: for
// a loop over a batch's gathers.
// (Always inlined, and in place: in the batch's lanes loop a call, or a copy of the whole
// sample that GCC does not split into its fields, keeps the loop scalar.)
// The weight is weight_for's from the values written, not read back from s (a read after a
// write of the same struct stopped GCC vectorising the loop).
template <bool kLanes = false, typename Real>
[[gnu::always_inline]] inline void Finish(GatherSample<Real>& s, const IntegrandFactors<Real>& f, const Medium<Real>& m,
                                          Real pdf) {
  const Real bare = FiniteOrZero<kLanes>(f.bare / pdf);
  s.bare_weight = bare;
  s.path_length = f.path_length;
  s.scatterings = f.scatterings;
  s.transmittance = PickExp<kLanes>(-m.sigma_t * f.connection);
  s.weight = FiniteOrZero<kLanes>(bare * MediumFactor<kLanes>(m.sigma_s, m.sigma_t, f.scatterings, f.path_length));
}
}  // namespace detail

}  // namespace vrlis
