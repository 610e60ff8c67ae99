#pragma once
// Vectors, colours, rays and random numbers shared by the whole pipeline.
#include <vrlis/core/phase.hpp>
#include <vrlis/core/vec3.hpp>

#include <pcg_random.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace vrlis::integration {

using Vec3f = vrlis::Vec3<float>;
using vrlis::Cross;
using vrlis::Dot;
using vrlis::Length;
using vrlis::Normalize;

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Rays start this far from their origin so that they do not hit the surface they leave.
inline constexpr float kRayEpsilon = 1e-4f;

// Linear RGB radiometric quantity.
struct Spectrum {
  float r = 0, g = 0, b = 0;
  Spectrum() = default;
  constexpr Spectrum(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
  explicit constexpr Spectrum(float v) : r(v), g(v), b(v) {}
  Spectrum& operator+=(Spectrum o) { r += o.r; g += o.g; b += o.b; return *this; }
  Spectrum& operator*=(Spectrum o) { r *= o.r; g *= o.g; b *= o.b; return *this; }
  Spectrum& operator*=(float s) { r *= s; g *= s; b *= s; return *this; }
  float MaxComponent() const { return std::max({r, g, b}); }
  float Average() const { return (r + g + b) / 3; }
  // The mean of the squared channels (in double), and its root: one number for a colour's size.
  double MeanSquare() const { return (double(r) * r + double(g) * g + double(b) * b) / 3; }
  float Rms() const { return static_cast<float>(std::sqrt(MeanSquare())); }
  bool IsBlack() const { return r == 0 && g == 0 && b == 0; }
};
inline Spectrum operator+(Spectrum a, Spectrum b) { return a += b; }
inline Spectrum operator*(Spectrum a, Spectrum b) { return a *= b; }
inline Spectrum operator*(Spectrum a, float s) { return a *= s; }
inline Spectrum operator*(float s, Spectrum a) { return a *= s; }

struct Ray {
  Vec3f o, d;  // d unit length
  Vec3f operator()(float t) const { return o + t * d; }
};

// A PCG32 stream named by (seed, pass, index, purpose): never by a thread, so images do
// not depend on the thread count.
enum class StreamPurpose : std::uint64_t { Camera = 1, LightPath = 2, LatticeRotation = 3, EffortModel = 4, EffortPair = 5 };

inline std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

class Rng {
 public:
  Rng(std::uint64_t seed, std::uint64_t pass, std::uint64_t index, StreamPurpose purpose)
      : pcg_(SplitMix64(seed ^ SplitMix64(pass + 0x51ed2701ull * static_cast<std::uint64_t>(purpose))),
             SplitMix64(index)) {}
  // Uniform in [0, 1): 24 random bits are exact in a float, so the largest value is 1 - 2^-24.
  float Uniform() { return static_cast<float>(pcg_() >> 8) * 0x1p-24f; }
  // A stream of its own for a part of the path whose number of draws varies (a gather under
  // the effort control): this stream advances by two numbers whatever the child draws, so
  // the rest of the path meets the same numbers with the control on or off.
  Rng Split() {
    std::uint64_t a = pcg_(), b = pcg_();
    return Rng(pcg32(SplitMix64((a << 32) | b), SplitMix64(b)));
  }

 private:
  explicit Rng(pcg32 pcg) : pcg_(pcg) {}
  pcg32 pcg_;
};

// An orthonormal frame around a unit vector.
struct Frame {
  Vec3f x, y, z;
  explicit Frame(Vec3f n) : x(vrlis::AnyPerpendicular(n)), y(Cross(n, x)), z(n) {}
  Vec3f FromLocal(float a, float b, float c) const { return a * x + b * y + c * z; }
};

inline Vec3f SphericalDirection(const Frame& f, float cos_theta, float phi) {
  float sin_theta = std::sqrt(std::max(0.f, 1 - cos_theta * cos_theta));
  return f.FromLocal(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

// Cosine-weighted direction about n: density max(0, n . w) / pi.
inline Vec3f SampleCosineHemisphere(Vec3f n, float u1, float u2) {
  return SphericalDirection(Frame(n), std::sqrt(1 - u1), 2 * kPi * u2);
}

// Henyey-Greenstein phase function, cos between the directions light travels before and
// after scattering.
inline float Phase(float g, float cos) { return vrlis::HenyeyGreenstein(g, std::clamp(cos, -1.f, 1.f)); }

// A new direction of travel for light travelling along w, with density Phase(g, w . w').
inline Vec3f SamplePhase(float g, Vec3f w, float u1, float u2) {
  return SphericalDirection(Frame(w), vrlis::SampleHenyeyGreenstein(g, u1), 2 * kPi * u2);
}

// The i-th of n points of a spherical Fibonacci lattice.
inline Vec3f FibonacciDirection(int i, int n) {
  const float golden = 2.39996322972865332f;  // pi (3 - sqrt 5)
  float z = 1 - (2 * i + 1) / static_cast<float>(n);
  return SphericalDirection(Frame({0, 0, 1}), z, golden * i);
}

// A rotation of 3D space, as the rows of its matrix.
struct Rotation {
  Vec3f row[3];
  Vec3f operator()(Vec3f v) const { return {Dot(row[0], v), Dot(row[1], v), Dot(row[2], v)}; }
};

// A uniformly random rotation (Haar measure on SO(3)) from three uniform numbers. A unit
// quaternion uniform on S^3 gives one, since q and -q name the same rotation and the
// measure on S^3 is invariant under quaternion multiplication. Uniform on S^3: of the two
// pairs of coordinates (w, z) and (x, y), the squared length of the second is uniform on
// [0, 1] (in R^4 the two pairs' squared lengths of a Gaussian vector are i.i.d.
// exponentials, so the ratio is uniform), and each pair's angle is uniform and independent.
inline Rotation UniformRotation(float u1, float u2, float u3) {
  const float a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const float t1 = 2 * kPi * u2, t2 = 2 * kPi * u3;
  const float w = a * std::cos(t1), z = a * std::sin(t1), x = b * std::cos(t2), y = b * std::sin(t2);
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}

}  // namespace vrlis::integration
