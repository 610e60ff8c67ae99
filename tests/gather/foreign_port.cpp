// A small renderer that is not ours, ported to vrlis as a new user ports it from the README:
// its own vector type (double), media stored as (sigma_a, sigma_s) per RGB channel, its gather
// loop over every beam of a camera segment. The port uses Medium's named factory, FromXyz and
// ToXyz, the one-call GatherMediumVrls and GatherSample::weight_for per channel. Hypothesis:
// per channel it is the library's grey gather run with that channel's coefficients, exactly
// at the same uniforms where sampling ignores sigma_t (Novák's samplers), in mean where it
// does not (FullProduct's). A negative control, the positional misfill {g, sigma_a, sigma_s},
// must fail both comparisons.
#include <catch2/catch.hpp>
#include <vrlis/core/running_moments.hpp>
#include <vrlis/vrlis.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "extern_gathers.hpp"

namespace tinyvrl {  // the foreign renderer's own types, in its own style

struct Vec {
  double x, y, z;
  Vec(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
};
struct Material {
  double g;
  double sigma_a[3], sigma_s[3];
};
struct Beam {
  Vec start, dir;
  double length;
  double power[3];
};
struct Ray {
  Vec o, d;
};
struct Rng {  // splitmix64
  std::uint64_t state;
  double next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return double((z ^ (z >> 31)) >> 11) * 0x1p-53;
  }
};
bool Occluded(const Vec& a, const Vec& b) { return a.y > 1.5 && b.y > 1.5; }  // a slab above y = 1.5

using Rgb = std::array<double, 3>;

}  // namespace tinyvrl

namespace {

using tinyvrl::Beam;
using tinyvrl::Material;
using tinyvrl::Rgb;
using tinyvrl::Vec;


// How the port turns the renderer's medium into vrlis's: by name (the port), or as the
// positional misfill {g, sigma_a, sigma_s} read as {g, sigma_s, sigma_t}, which no longer
// compiles and is spelled here by the factory it would have meant.
using MakeMedium = vrlis::Medium<float> (*)(double g, double sigma_a, double sigma_s);
vrlis::Medium<float> Named(double g, double sigma_a, double sigma_s) {
  return vrlis::Medium<float>::FromAbsorptionScattering(float(g), float(sigma_a), float(sigma_s));
}
vrlis::Medium<float> Positional(double g, double sigma_a, double sigma_s) {
  return vrlis::Medium<float>::FromScatteringExtinction(float(g), float(sigma_a), float(sigma_s));
}

// The port: RGB radiance at ray.o from every beam scattered on [tmin, tmax]. Sampling uses
// the channels' mean medium; each channel weighs the same sample with its own coefficients.
Rgb PortedGather(const Material& m, const tinyvrl::Ray& ray, double tmin, double tmax, const std::vector<Beam>& beams,
                 vrlis::GatherSamplers method, tinyvrl::Rng& rng, MakeMedium make) {
  const vrlis::Medium<float> grey =
      make(m.g, (m.sigma_a[0] + m.sigma_a[1] + m.sigma_a[2]) / 3, (m.sigma_s[0] + m.sigma_s[1] + m.sigma_s[2]) / 3);
  std::array<vrlis::Medium<float>, 3> channel;
  for (int c = 0; c < 3; ++c) channel[c] = make(m.g, m.sigma_a[c], m.sigma_s[c]);
  std::vector<vrlis::VrlSegment<float>> vrls;
  for (const Beam& b : beams) vrls.push_back({vrlis::FromXyz<float>(b.start), vrlis::FromXyz<float>(b.dir), float(b.length)});
  const vrlis::RaySegment<float> camera{vrlis::FromXyz<float>(ray.o), vrlis::FromXyz<float>(ray.d), float(tmin), float(tmax)};
  Rgb sum{};
  vrlis::GatherMediumVrls(method, camera, grey, vrls.data(), int(vrls.size()),
                          [&] { return float(rng.next()); },
                          [&](int i, const vrlis::GatherSample<float>& s, float effort_weight) {
                            if (!(s.bare_weight > 0) ||
                                tinyvrl::Occluded(vrlis::ToXyz<Vec>(s.camera_point), vrlis::ToXyz<Vec>(s.light_point)))
                              return;
                            for (int c = 0; c < 3; ++c) sum[c] += beams[i].power[c] * s.weight_for(channel[c]) * effort_weight;
                          });
  return sum;
}

// The library's grey gather of channel c: the same call with that channel's medium, drawing
// the same numbers, its own weight.
double GreyGather(const Material& m, int c, const tinyvrl::Ray& ray, double tmin, double tmax,
                  const std::vector<Beam>& beams, vrlis::GatherSamplers method, tinyvrl::Rng& rng) {
  const vrlis::RaySegment<float> camera{{float(ray.o.x), float(ray.o.y), float(ray.o.z)},
                                        {float(ray.d.x), float(ray.d.y), float(ray.d.z)}, float(tmin), float(tmax)};
  const auto medium = vrlis::Medium<float>::FromAbsorptionScattering(float(m.g), float(m.sigma_a[c]), float(m.sigma_s[c]));
  std::vector<vrlis::VrlSegment<float>> vrls;
  for (const Beam& b : beams)
    vrls.push_back({{float(b.start.x), float(b.start.y), float(b.start.z)}, {float(b.dir.x), float(b.dir.y), float(b.dir.z)},
                    float(b.length)});
  double sum = 0;
  vrlis::GatherMediumVrls(method, camera, medium, vrls.data(), int(vrls.size()),
                          [&] { return float(rng.next()); },
                          [&](int i, const vrlis::GatherSample<float>& s, float) {
                            if (s.contributes() && !tinyvrl::Occluded({s.camera_point.x, s.camera_point.y, s.camera_point.z},
                                                                      {s.light_point.x, s.light_point.y, s.light_point.z}))
                              sum += beams[i].power[c] * s.weight;
                          });
  return sum;
}

const Material kMaterial{0.6, {0.05, 0.1, 0.3}, {0.5, 0.3, 0.1}};
const tinyvrl::Ray kRay{{0, 0, 0}, {0, 0, -1}};
constexpr double kTmin = 0.5, kTmax = 8;

std::vector<Beam> Beams() {
  auto unit = [](double x, double y, double z) {
    double n = std::sqrt(x * x + y * y + z * z);
    return Vec(x / n, y / n, z / n);
  };
  return {{Vec(1, -1, -3), unit(0, 1, 0), 3, {1, 0.8, 0.6}},
          {Vec(-2, 0.5, -1), unit(1, 0.2, -1), 4, {0.3, 0.5, 1}},
          {Vec(0.2, 2, -5), unit(0, -1, 0.1), 2.5, {2, 1, 0.5}},
          {Vec(0.5, 0.5, -2), unit(-1, 1, 1), 1.5, {0.7, 0.7, 0.7}}};
}

TEST_CASE("a foreign renderer's RGB gather loop ported to vrlis is the grey gather per channel", "[gather][port]") {
  const std::vector<Beam> beams = Beams();
  const vrlis::GatherSamplers novak = *vrlis::ParseGatherSamplers("novak");

  SECTION("at the same uniforms, with samplers that ignore sigma_t: equal") {
    for (int k = 0; k < 200; ++k) {
      tinyvrl::Rng port_rng{std::uint64_t(k)}, misfill_rng{std::uint64_t(k)};
      const Rgb port = PortedGather(kMaterial, kRay, kTmin, kTmax, beams, novak, port_rng, Named);
      const Rgb misfill = PortedGather(kMaterial, kRay, kTmin, kTmax, beams, novak, misfill_rng, Positional);
      for (int c = 0; c < 3; ++c) {
        tinyvrl::Rng rng{std::uint64_t(k)};
        const double grey = GreyGather(kMaterial, c, kRay, kTmin, kTmax, beams, novak, rng);
        INFO("run " << k << " channel " << c << ": port " << port[c] << ", grey " << grey << ", misfill " << misfill[c]);
        CHECK(port[c] == Approx(grey).epsilon(1e-6).margin(1e-30));
        if (grey > 0) CHECK(misfill[c] != Approx(grey).epsilon(0.05));
      }
    }
  }

  SECTION("with FullProduct, whose sampling follows sigma_t: equal in mean") {
    const vrlis::GatherSamplers full = *vrlis::ParseGatherSamplers("full-product");
    const double critical = 3.4;  // two-sided 1 % over the six comparisons below (Bonferroni)
    std::array<vrlis::RunningMoments, 3> port, misfill, grey;
    tinyvrl::Rng port_rng{1}, misfill_rng{2}, grey_rng{3};
    for (int k = 0; k < 40000; ++k) {
      const Rgb p = PortedGather(kMaterial, kRay, kTmin, kTmax, beams, full, port_rng, Named);
      const Rgb w = PortedGather(kMaterial, kRay, kTmin, kTmax, beams, full, misfill_rng, Positional);
      for (int c = 0; c < 3; ++c) {
        port[c].add(p[c]);
        misfill[c].add(w[c]);
        grey[c].add(GreyGather(kMaterial, c, kRay, kTmin, kTmax, beams, full, grey_rng));
      }
    }
    auto z = [&](const vrlis::RunningMoments& a, const vrlis::RunningMoments& b) {
      return (a.mean() - b.mean()) / std::hypot(a.standard_error(), b.standard_error());
    };
    for (int c = 0; c < 3; ++c) {
      INFO("channel " << c << ": port " << port[c].mean() << ", grey " << grey[c].mean() << ", misfill "
                      << misfill[c].mean());
      CHECK(std::abs(z(port[c], grey[c])) < critical);
      CHECK(std::abs(z(misfill[c], grey[c])) > critical);
    }
  }
}

}  // namespace
