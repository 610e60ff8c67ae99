// Hypotheses: the batched gathers are the one-VRL gathers.
//
// Medium to medium: for every step one x step two,
// SampleMediumGathers over a camera segment and n VRLs (n from 1 to past one chunk of
// kGatherChunk gathers) returns, VRL by VRL:
// - step one's sample v and density: the one-VRL gather's to rounding. The lanes take square
//   roots by Newton steps and VrlPoint by the instruction, so v agrees to the rounding of a
//   position on the VRL, and the density to that rounding times its condition: an error dx in
//   x = k (v - v0) moves p ~ 1 / sqrt(1 + x^2) by at most |dx| / 2 relatively, and rounding
//   leaves |dx| within a few eps (1 + k L) (x passes near 0 only within k L of the ends);
// - given that VRL point, the one-VRL camera step's sample, in angle and density to the
//   resolution of t (SameSegmentSample): the same code, the batch's in vector lanes (angle
//   domains, points and weights), whose sines, exponentials and square roots round
//   differently by a few ulp;
// - a weight that is the integrand at its own two points over their densities, to rounding,
//   and the connection's transmittance there. (Not the one-VRL gather's weight: where the
//   camera point lies within a thousandth of the VRL point, the ulp of t that the lanes'
//   sine moves takes the weight's 1 / r^2 by 5e-4.)
// (Not the whole one-VRL gather from the same random numbers: next to the camera line the
// camera step turns an ulp of the VRL point into percents of its density, and a fit's node
// split into a different fit.) The VRLs are random and include the cases step one treats
// apart: v0 before, inside and after the VRL, near-parallel lines, a VRL crossing the camera
// line, tiny and long VRLs, and runs of one VRL (a split gather's samples, which share step
// one's fit). A batch that mixed up lanes, fits or random numbers fails on the first sample.
// For `auto` the lanes' rule (AutoAngle::ChooseLanes) must have chosen each lane's model as
// the one-VRL rule did, and the queries compared take each of its three models.
//
// Medium to surface: for every VRL sampler, SampleSurfaceGathers over a surface point and n
// VRLs (with runs of one VRL, which share a fit) returns, VRL by VRL, the one-VRL gather
// (SampleSurfaceGather) from the same random number: the same code from the same inputs,
// equal to rounding.
//
// Both, on the widest vector lanes the processor has (AVX2 where a default x86-64 build has
// SSE; core/dispatch.hpp) and as built: the same code compiled twice, without contracted
// multiply-adds on either, so equal to rounding too.
#include <catch2/catch.hpp>
#include <vrlis/vrlis.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "extern_gathers.hpp"

namespace {

template <typename Real>
vrlis::VrlSegment<Real> RandomVrl(std::mt19937& rng, int kind) {
  std::uniform_real_distribution<double> uniform(-1, 1);
  auto unit = [&] {
    vrlis::Vec3<double> d{uniform(rng), uniform(rng), uniform(rng)};
    return vrlis::Normalize(d);
  };
  vrlis::Vec3<double> origin{3 * uniform(rng), 3 * uniform(rng), -1 - 4 * std::abs(uniform(rng))}, dir = unit();
  double length = std::exp(3 * uniform(rng));
  switch (kind % 4) {
    case 1:  // nearly parallel to the camera line (0, 0, -1)
      dir = vrlis::Normalize(vrlis::Vec3<double>{1e-5 * uniform(rng), 1e-5 * uniform(rng), -1});
      break;
    case 2:  // through the camera line: starts before it, crosses it mid-way
      origin = vrlis::Vec3<double>{0, 0, -2} - (0.5 * length) * dir;
      break;
    case 3:  // tiny
      length = 1e-4 * std::abs(uniform(rng));
      break;
  }
  return {{Real(origin.x), Real(origin.y), Real(origin.z)}, vrlis::Normalize(vrlis::Vec3<Real>{Real(dir.x), Real(dir.y), Real(dir.z)}),
          Real(length)};
}

// Equal up to rounding (64 epsilon relative, or of `scale`): scalar code and lanes round
// square roots differently, and contracted multiply-adds when the build enables FMA. Any
// mix-up of VRLs or random numbers is off by far more.
template <typename Real>
bool Close(Real a, Real b, double scale = 0) {
  return std::abs(double(a) - double(b)) <=
         64 * std::numeric_limits<Real>::epsilon() * std::max({double(std::abs(a)), double(std::abs(b)), scale});
}

// A point's coordinates to the rounding of the point (a coordinate near 0 where origin and
// offset cancel keeps only the absolute error of the larger ones), the rest to their own.
template <typename Real>
bool SamePoint(vrlis::Vec3<Real> a, vrlis::Vec3<Real> b) {
  const double size = std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z), std::abs(b.x), std::abs(b.y), std::abs(b.z)});
  return Close(a.x, b.x, size) && Close(a.y, b.y, size) && Close(a.z, b.z, size);
}
template <typename Real>
bool Same(const vrlis::GatherSample<Real>& a, const vrlis::GatherSample<Real>& b) {
  const Real fa[] = {a.t, a.pdf_t, a.v, a.pdf_v, a.transmittance, a.weight};
  const Real fb[] = {b.t, b.pdf_t, b.v, b.pdf_v, b.transmittance, b.weight};
  for (int i = 0; i < 6; ++i)
    if (!Close(fa[i], fb[i])) return false;
  return SamePoint(a.camera_point, b.camera_point) && SamePoint(a.light_point, b.light_point);
}


// A batch's sample (t, pdf, point) on a segment against the one-at-a-time sampler's, one_t,
// from the same query (sampler; at(t) the segment's point): to the resolution of t (4 ulp
// either side), the same angle and the sampler's density, and the point at t. Not the same
// t: at a grazing angle t = u0 + h tan(theta) turns an ulp of the angle's sine and cosine
// into 1e-5 of t, and the lanes' sine rounds differently from libm's; and where the point
// seen lies next to the segment's line (h small) an ulp of t is a wide angle, over which the
// density changes by 1e-4.
template <typename Sampler, typename Real, typename At>
bool SameSegmentSample(Real t, Real pdf, vrlis::Vec3<Real> point, Real one_t, const Sampler& sampler, At&& at) {
  Real lo = t, hi = t;
  for (int k = 0; k < 4; ++k)
    lo = std::nextafter(lo, -std::numeric_limits<Real>::infinity()),
    hi = std::nextafter(hi, std::numeric_limits<Real>::infinity());
  // x is f(t) to rounding, or to f's change over the resolution of t.
  auto near = [&](double x, double (*f)(const Sampler&, Real), double scale) {
    const double lo_f = f(sampler, lo), at_t = f(sampler, t), hi_f = f(sampler, hi);
    const double spread = std::max({lo_f, at_t, hi_f}) - std::min({lo_f, at_t, hi_f});
    return std::abs(x - at_t) <= 64 * std::numeric_limits<Real>::epsilon() * std::max(scale, std::abs(at_t)) + spread;
  };
  auto angle = [](const Sampler& sm, Real x) { return double(sm.domain().offset_at(x)); };
  auto density = [](const Sampler& sm, Real x) { return double(sm.pdf(x)); };
  return near(sampler.domain().offset_at(one_t), angle, 1) && near(pdf, density, 0) && SamePoint(point, at(t));
}

// The sample's weight is the integrand's factors f at its own points over its density pdf,
// and its transmittance the connection's, to rounding: of the distances too (the lanes'
// square roots round differently by a few ulp), which the exponentials multiply by the
// optical depth; and a subnormal weight keeps only absolute digits. The medium's factors in
// double: in float a far sample's integrand is itself subnormal before its division by the
// density.
template <typename Real>
bool WeighsItsPoints(const vrlis::GatherSample<Real>& s, const vrlis::IntegrandFactors<Real>& f, double pdf,
                     const vrlis::Medium<Real>& medium) {
  const double sigma_s = medium.sigma_s, sigma_t = medium.sigma_t;
  const double weight = double(f.bare) / pdf * (f.scatterings == 2 ? sigma_s * sigma_s : sigma_s) *
                        std::exp(-sigma_t * double(f.path_length));
  const double transmittance = std::exp(-sigma_t * double(f.connection));
  const double depth = 1 + sigma_t * double(s.path_length);
  auto near = [&](Real a, double b) {
    return std::abs(double(a) - b) <= 64 * std::numeric_limits<Real>::epsilon() *
                                          (depth * std::max(std::abs(double(a)), std::abs(b)) +
                                           double(std::numeric_limits<Real>::min()));
  };
  return near(s.weight, weight) && near(s.transmittance, transmittance);
}

// k L of step one's density for this VRL and camera line, in double: L sin^2(a) / |d . (w_l x w_c)|.
template <typename Real>
double StepOneSpread(const vrlis::RaySegment<Real>& camera, const vrlis::VrlSegment<Real>& vrl) {
  auto v = [](vrlis::Vec3<Real> a) { return vrlis::Vec3<double>{a.x, a.y, a.z}; };
  vrlis::Vec3<double> cross = vrlis::Cross(v(vrl.dir), v(camera.dir)), d = v(camera.origin) - v(vrl.origin);
  return double(vrl.length) * vrlis::Dot(cross, cross) / std::abs(vrlis::Dot(d, cross));
}

template <typename Real>
void BatchIsOneAtATime(bool widest) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<Real> uniform(0, 1);
  // g > 0; g < 0 in a denser medium (the segment lobe peaks at the far pole, and FullProduct's
  // fit splits where it meets the transmittance); g = 0 (flat lobes: no splits, no Cauchys).
  using M = vrlis::Medium<Real>;
  const M media[] = {M::FromScatteringExtinction(Real(0.6), Real(0.4), Real(0.5)),
                     M::FromScatteringExtinction(Real(-0.7), Real(0.8), Real(1.5)),
                     M::FromScatteringExtinction(Real(0), Real(0.4), Real(0.5))};
  int models[3] = {};  // auto's compared samples by their model (AutoModel)
  for (const vrlis::Medium<Real>& medium : media)
    for (vrlis::VrlChoice one : vrlis::kVrlSamplers)
      for (vrlis::SegmentChoice two : vrlis::kSegmentSamplers) {
        vrlis::GatherSamplers method{two, one};
        int compared = 0, contributing = 0;
        // Part of one vector of lanes, whole ones, part of a chunk, a whole chunk and past it.
        for (int n : {1, 2, 3, 5, 7, 8, 9, 11, 13, 16, 17, 19, vrlis::kGatherChunk - 1, vrlis::kGatherChunk,
                      vrlis::kGatherChunk + 3}) {
          const vrlis::RaySegment<Real> camera{{0, 0, 0}, {0, 0, -1}, Real(0.5) * uniform(rng),
                                                   n % 5 ? Real(8) : std::numeric_limits<Real>::infinity()};
          std::vector<vrlis::VrlSegment<Real>> vrls;
          std::vector<Real> u_vrl, u_camera;
          for (int i = 0; i < n; ++i) {
            vrls.push_back(i % 3 == 1 ? vrls.back() : RandomVrl<Real>(rng, i + n));  // runs of a split gather
            u_vrl.push_back(uniform(rng));
            u_camera.push_back(uniform(rng));
          }
          std::vector<vrlis::GatherSample<Real>> batch(n);
          vrlis::WithGatherSamplers<Real>(method, [&](auto step_one, auto step_two) {
            vrlis::SampleMediumGathers<typename decltype(step_one)::type, typename decltype(step_two)::type>(
                vrlis::ValidQuery{}, camera, medium, vrls.data(), n, u_vrl.data(), u_camera.data(), batch.data(), false,
                widest);
          });
          for (int i = 0; i < n; ++i) {
            vrlis::MediumGatherQuery<Real> q{camera, vrls[i], medium};
            REQUIRE(vrlis::Validate(q) == vrlis::QueryError::None);
            INFO(vrlis::Name(method) << ", g " << medium.g << ", batch of " << n << ", VRL " << i);
            vrlis::GatherSample<Real> one = vrlis::SampleMediumGather(method, q, u_vrl[i], u_camera[i]);
            // (The lanes' exponential flushes a subnormal weight to 0: nothing to trace either way.)
            const bool negligible = std::max(batch[i].weight, one.weight) < std::numeric_limits<Real>::min();
            REQUIRE((batch[i].contributes() == one.contributes() || negligible));
            ++compared;
            if (!one.contributes() || !batch[i].contributes()) continue;
            ++contributing;
            REQUIRE(Close(batch[i].v, one.v, double(vrls[i].length)));
            REQUIRE(Close(batch[i].pdf_v, one.pdf_v, (1 + StepOneSpread(camera, vrls[i])) * double(one.pdf_v)));
            REQUIRE(WeighsItsPoints(batch[i], vrlis::MediumGatherFactors(q, batch[i].t, batch[i].v),
                                    double(batch[i].pdf_t) * double(batch[i].pdf_v), medium));
            vrlis::WithGatherSamplers<Real>(method, [&](auto, auto step_two) {
              using CameraSampler = typename decltype(step_two)::type;
              const vrlis::Vec3<Real> y = q.vrl.at(batch[i].v);
              const CameraSampler sampler(vrlis::ValidQuery{}, vrlis::CameraStepQuery(q, y));
              if constexpr (std::is_same_v<CameraSampler, vrlis::Auto<Real>>)
                ++models[static_cast<int>(sampler.distribution().model())];
              REQUIRE(SameSegmentSample(batch[i].t, batch[i].pdf_t, batch[i].camera_point,
                                        sampler.sample_pdf(u_camera[i]).t, sampler,
                                        [&](Real t) { return camera.at(t); }));
              REQUIRE(SamePoint(batch[i].light_point, y));
            });
          }
        }
        CHECK(contributing > compared / 2);  // the comparison is of estimates, not of empty samples
      }
}

template <typename Real>
void SurfaceBatchIsOneAtATime(bool widest) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<Real> uniform(0, 1);
  const auto medium = vrlis::Medium<Real>::FromScatteringExtinction(Real(0.6), Real(0.4), Real(0.5));
  const vrlis::Vec3<Real> point{0, 0, -2}, normal = vrlis::Normalize(vrlis::Vec3<Real>{Real(0.3), Real(-0.2), Real(-1)});
  for (vrlis::SegmentChoice method : vrlis::kSegmentSamplers) {
    int contributing = 0, compared = 0;
    for (int n : {1, 2, 3, 5, 8, 9, 13, 17, 19, vrlis::kGatherChunk, vrlis::kGatherChunk + 3}) {
      std::vector<vrlis::VrlSegment<Real>> vrls;
      std::vector<Real> u;
      for (int i = 0; i < n; ++i) {
        vrls.push_back(i % 3 == 1 ? vrls.back() : RandomVrl<Real>(rng, i + n));  // runs of a split gather
        u.push_back(uniform(rng));
      }
      std::vector<vrlis::GatherSample<Real>> batch(n);
      vrlis::SegmentSamplers::WithEntry(method, [&](auto entry) {
        vrlis::SampleSurfaceGathers<typename decltype(entry)::template Sampler<Real>>(
            vrlis::ValidQuery{}, point, normal, medium, vrls.data(), n, u.data(), batch.data(), false, widest);
      });
      for (int i = 0; i < n; ++i) {
        vrlis::SurfaceGatherQuery<Real> q{point, normal, vrls[i], medium};
        REQUIRE(vrlis::Validate(q) == vrlis::QueryError::None);
        INFO(vrlis::Name(method) << ", batch of " << n << ", VRL " << i);
        vrlis::GatherSample<Real> one = vrlis::SampleSurfaceGather(method, q, u[i]);
        REQUIRE(batch[i].contributes() == one.contributes());
        ++compared;
        if (!one.contributes()) continue;
        ++contributing;
        REQUIRE(Same(batch[i], one));
      }
    }
    CHECK(contributing > compared / 4);  // enough VRLs face the surface to compare estimates
  }
}

// Runs check(widest) on both instruction-set paths (core/dispatch.hpp): the widest the
// processor has, and as built.
template <typename Check>
void OnBothPaths(Check&& check) {
  const bool widest = GENERATE(true, false);
  INFO("widest lanes " << widest << " (available: " << vrlis::detail::WidestLanesAvailable() << ")");
  check(widest);
}
}  // namespace

TEST_CASE("batched surface gather: the one-VRL gather to rounding, every sampler (float)") {
  OnBothPaths(SurfaceBatchIsOneAtATime<float>);
}
TEST_CASE("batched surface gather: the one-VRL gather to rounding, every sampler (double)") {
  OnBothPaths(SurfaceBatchIsOneAtATime<double>);
}

TEST_CASE("batched medium gather: the one-VRL gather to rounding, every method (float)") {
  OnBothPaths(BatchIsOneAtATime<float>);
}
TEST_CASE("batched medium gather: the one-VRL gather to rounding, every method (double)") {
  OnBothPaths(BatchIsOneAtATime<double>);
}
