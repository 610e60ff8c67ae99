#pragma once
// The light sources the scenes need: a point light (isotropic, or emitting along a
// Fibonacci set of beams) and a rectangle emitting a collimated beam.
//
// Units: a point light has intensity I (W/sr per channel), power 4 pi I; a beam light of N
// beams has power 4 pi I too, split evenly. A collimated rectangle has irradiance E (W/m^2)
// on the plane perpendicular to its beam and power E A |n . d|.
#include <optional>
#include <vector>

#include "common.hpp"

namespace vrlis::integration {

struct PointLight {
  Vec3f position{};
  Spectrum intensity{};
  // Light path i of N leaves along FibonacciDirection(i, N), turned by one uniformly random
  // rotation per pass: every beam is then uniform on the sphere, and the passes converge
  // to the isotropic light's image. Without the rotation the beams are the same in every
  // pass and the image is that of the N fixed beams.
  bool fibonacci_beams = false;
  bool rotate_lattice = true;
};

struct CollimatedRect {
  Vec3f corner{}, edge1{}, edge2{};  // the rectangle corner + s edge1 + t edge2, s, t in [0, 1]
  Vec3f direction{};                 // unit, the beam's direction of travel
  Spectrum irradiance{};

  Vec3f Normal() const { return Normalize(Cross(edge1, edge2)); }
  float Area() const { return Length(Cross(edge1, edge2)); }
  // Where the beam arriving at p comes from, if p is lit by it (occlusion aside).
  std::optional<Vec3f> Source(Vec3f p) const {
    Vec3f n = Normal();
    float denom = Dot(direction, n);
    if (denom == 0) return std::nullopt;
    float t = Dot(p - corner, n) / denom;  // p - t direction is on the plane
    if (!(t > 0)) return std::nullopt;
    Vec3f q = p - t * direction, e = q - corner;
    float s = Dot(e, edge1) / Dot(edge1, edge1), r = Dot(e, edge2) / Dot(edge2, edge2);
    if (s < 0 || s > 1 || r < 0 || r > 1) return std::nullopt;
    return q;
  }
};

struct Lights {
  std::vector<PointLight> points;
  std::vector<CollimatedRect> rects;

  // Power per channel averaged: the weight for choosing a light to start a path from.
  std::vector<float> Powers() const {
    std::vector<float> p;
    for (const PointLight& l : points) p.push_back(4 * kPi * l.intensity.Average());
    for (const CollimatedRect& l : rects)
      p.push_back(l.irradiance.Average() * l.Area() * std::abs(Dot(l.Normal(), l.direction)));
    return p;
  }
};

// Light arriving at a point from one light, for next-event estimation: radiance-like value
// (intensity / r^2 or irradiance) along direction wi (towards the light), before
// transmittance and visibility, which the caller applies between the point and `source`.
struct LightSample {
  Vec3f wi{}, source{};
  Spectrum value{};
};

inline std::optional<LightSample> SampleLight(const PointLight& l, Vec3f p) {
  if (l.fibonacci_beams) return std::nullopt;  // delta directions: no connection possible
  Vec3f d = l.position - p;
  float r2 = Dot(d, d);
  if (!(r2 > 0)) return std::nullopt;
  return LightSample{(1 / std::sqrt(r2)) * d, l.position, l.intensity * (1 / r2)};
}

inline std::optional<LightSample> SampleLight(const CollimatedRect& l, Vec3f p) {
  std::optional<Vec3f> q = l.Source(p);
  if (!q) return std::nullopt;
  return LightSample{-l.direction, *q, l.irradiance};
}

}  // namespace vrlis::integration
