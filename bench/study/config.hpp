#pragma once
// Random VRL / camera segment pairs in an infinite homogeneous medium, shared by the
// benchmarks, the accuracy study and its test. Everything is seeded and portable: the
// generator is SplitMix64 and the uniforms are built from its bits, so a seed gives the
// same pairs with every compiler and standard library.
#include <cmath>
#include <cstdint>
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

// A camera segment x(u) = xc + u wc, u in [0, s], and a VRL y(v) = xl + v wl, v in [0, t],
// in a medium with extinction sigma_t (the mean free path is 1 / sigma_t) and HG(g).
template <typename Real>
struct Pair {
  Vec3<Real> xc{}, wc{};
  Real s = 0;
  Vec3<Real> xl{}, wl{};
  Real t = 0;
  Real g = 0;
  Real sigma_t = 1;
  Real xi_vrl = Real(0.5);  // the fixed VRL point of the camera-step study: VrlPoint.sample(xi_vrl)
  Real xi_cam = Real(0.5);  // a second uniform, for benchmarks that need one

  template <typename Other>
  Pair<Other> as() const {
    auto cv = [](Vec3<Real> a) { return Vec3<Other>{Other(a.x), Other(a.y), Other(a.z)}; };
    return {cv(xc), cv(wc), Other(s), cv(xl), cv(wl), Other(t), Other(g), Other(sigma_t), Other(xi_vrl), Other(xi_cam)};
  }
};

// Lengths and distances of the order of the mean free path and a few times it (sigma_t = 1):
// segment lengths log-uniform in [0.25, 4]; the VRL starts at a distance log-uniform in
// [0.1, 3] from a uniform point of the camera segment, in a uniform direction, and runs in
// a uniform direction.
inline Pair<double> RandomPair(Rng& rng, double g) {
  Pair<double> p;
  p.xc = {0, 0, 0};
  p.wc = rng.direction();
  p.s = rng.log_uniform(0.25, 4);
  Vec3<double> anchor = p.xc + rng.uniform(0, p.s) * p.wc;
  p.xl = anchor + rng.log_uniform(0.1, 3) * rng.direction();
  p.wl = rng.direction();
  p.t = rng.log_uniform(0.25, 4);
  p.g = g;
  p.sigma_t = 1;
  p.xi_vrl = rng.uniform();
  p.xi_cam = rng.uniform();
  return p;
}

// The same geometry for every g (only g changes), so results across g are comparable.
inline std::vector<Pair<double>> MakePairs(std::uint64_t seed, int count, double g) {
  Rng rng(seed);
  std::vector<Pair<double>> pairs;
  pairs.reserve(count);
  for (int i = 0; i < count; ++i) pairs.push_back(RandomPair(rng, g));
  return pairs;
}

inline constexpr double kStudyG[] = {-0.99, -0.9, -0.5, -0.3, 0, 0.3, 0.5, 0.7, 0.9, 0.99};
inline constexpr std::uint64_t kDefaultSeed = 20240611;

// Step one: the query of Novák's VRL-point sampler for this pair.
template <typename Real>
VrlPointQuery<Real> VrlQuery(const Pair<Real>& p) {
  return {p.xl, p.wl, Real(0), p.t, p.xc, p.wc};
}

// Step one following the marginal of the whole integrand (VrlMarginal): the camera
// segment, g and sigma_t as well.
template <typename Real>
MediumGatherQuery<Real> MarginalQuery(const Pair<Real>& p) {
  return {{p.xc, p.wc, Real(0), p.s}, {p.xl, p.wl, p.t}, {p.g, p.sigma_t, p.sigma_t}};
}

template <typename Real>
Vec3<Real> VrlPointAt(const Pair<Real>& p, Real v) { return p.xl + v * p.wl; }

// Step two: the camera segment seen from the VRL point y, with the VRL's lobe at y.
template <typename Real>
SegmentQuery<Real> CameraQuery(const Pair<Real>& p, Vec3<Real> y) {
  return MediumToMediumQuery(p.xc, p.wc, Real(0), p.s, y, p.wl, p.g, p.sigma_t);
}

}  // namespace vrlis::study
