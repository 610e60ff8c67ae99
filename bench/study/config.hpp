#pragma once
// Random medium-to-medium gather queries in an infinite homogeneous medium, shared by the
// benchmarks, the accuracy study and its test. Everything is seeded and portable: the
// generator is SplitMix64 and the uniforms are built from its bits, so a seed gives the
// same queries with every compiler and standard library.
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <vrlis/vrlis.hpp>

namespace vrlis::study {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  double log_uniform(double a, double b) { return a * std::exp(std::log(b / a) * uniform()); }
  Vec3<double> direction() {  // uniform on the sphere
    double z = uniform(-1, 1), phi = uniform(0, 2 * kPi<double>), s = std::sqrt(std::max(0.0, 1 - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
  }

 private:
  std::uint64_t state_;
};

// One configuration of the study: the library's gather query, and the two uniforms that fix
// its VRL point (the camera-step study: VrlPoint.sample(xi_vrl)) and its camera point (the
// benchmarks).
template <typename Real>
struct Config {
  MediumGatherQuery<Real> query;
  Real xi_vrl = Real(0.5), xi_cam = Real(0.5);

  template <typename Other>
  Config<Other> as() const {
    auto v = [](Vec3<Real> a) { return Vec3<Other>{Other(a.x), Other(a.y), Other(a.z)}; };
    const auto& c = query.camera;
    const auto& l = query.vrl;
    const auto& m = query.medium;
    MediumGatherQuery<Other> q{{v(c.origin), v(c.dir), Other(c.tmin), Other(c.tmax)},
                               {v(l.origin), v(l.dir), Other(l.length)},
                               Medium<Other>::FromScatteringExtinction(Other(m.g), Other(m.sigma_s), Other(m.sigma_t))};
    return {q, Other(xi_vrl), Other(xi_cam)};
  }
};

// The synthetic distribution, in mean free paths (mfp = 1 / sigma_t), wide enough to hold
// the configurations the scenes make (docs/accuracy_scenes.md: segments and VRLs up to 14
// mfp, camera segments passing within 0.05 mfp of a VRL and running on for many mfp):
// camera segments from the origin, log-uniform in [0.25, 20] mfp, one in eight unbounded;
// VRLs log-uniform in [0.25, 20] mfp, starting at a distance log-uniform in [0.01, 3] mfp
// from a uniform point of the camera segment's first 4 mfp, in uniform directions. A
// relative variance depends on lengths in mfp only (scaling every length leaves it
// unchanged), so sigma_t, log-uniform in [0.05, 5], varies the samplers' arithmetic rather
// than the study. Scattering albedo 0.7 (a constant factor, it cancels).
inline Config<double> RandomConfig(Rng& rng, double g) {
  Config<double> c;
  double sigma_t = rng.log_uniform(0.05, 5), mfp = 1 / sigma_t;
  auto& cam = c.query.camera;
  cam.origin = {0, 0, 0};
  cam.dir = rng.direction();
  cam.tmin = 0;
  double length = rng.log_uniform(0.25, 20) * mfp;
  cam.tmax = rng.uniform() < 0.125 ? std::numeric_limits<double>::infinity() : length;
  Vec3<double> anchor = cam.at(rng.uniform(0, std::min(length, 4 * mfp)));
  auto& vrl = c.query.vrl;
  vrl.origin = anchor + rng.log_uniform(0.01, 3) * mfp * rng.direction();
  vrl.dir = rng.direction();
  vrl.length = rng.log_uniform(0.25, 20) * mfp;
  c.query.medium = Medium<double>::FromScatteringExtinction(g, 0.7 * sigma_t, sigma_t);
  c.xi_vrl = rng.uniform();
  c.xi_cam = rng.uniform();
  return c;
}

inline constexpr const char* kSyntheticDescription =
    "infinite homogeneous, sigma_t log-uniform [0.05, 5]; camera segments log-uniform [0.25, 20] mfp, one in eight "
    "unbounded; VRLs log-uniform [0.25, 20] mfp; VRL start at a distance log-uniform [0.01, 3] mfp from a uniform "
    "point of the camera segment's first 4 mfp";

// The same geometry for every g (only g changes), so results across g are comparable.
inline std::vector<Config<double>> MakeConfigs(std::uint64_t seed, int count, double g) {
  Rng rng(seed);
  std::vector<Config<double>> configs;
  configs.reserve(count);
  for (int i = 0; i < count; ++i) configs.push_back(RandomConfig(rng, g));
  return configs;
}

inline constexpr double kStudyG[] = {-0.99, -0.9, -0.5, -0.3, 0, 0.3, 0.5, 0.7, 0.9, 0.99};
inline constexpr std::uint64_t kDefaultSeed = 20240611;

}  // namespace vrlis::study
