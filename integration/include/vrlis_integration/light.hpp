#pragma once
// The light sources the scenes need: a point light (isotropic, a spot light with a hard
// cone, or emitting along a Fibonacci set of beams) and a rectangle emitting a collimated
// beam.
//
// Units: a point light has intensity I (W/sr per channel), power 4 pi I, or 2 pi (1 - cos c) I
// within a cone of half-angle c; a beam light of N beams has power 4 pi I too, split evenly.
// A collimated rectangle has irradiance E (W/m^2) on the plane perpendicular to its beam and
// power E A |n . d|.
#include <optional>
#include <utility>
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
  Vec3f axis{0, 0, -1};  // a spot light's unit axis
  float cos_cone = -1;   // cos of its half-angle: -1 for a light emitting everywhere

  // The solid angle it emits into.
  float SolidAngle() const { return 2 * kPi * (1 - cos_cone); }
  // Whether it emits towards p.
  bool Lights(Vec3f p) const {
    Vec3f d = p - position;
    return cos_cone <= -1 || Dot(d, axis) >= cos_cone * Length(d);
  }
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
  // The part of [lo, hi] along the ray inside the beam (where Source is defined): the
  // distance back to the plane and both rectangle coordinates are linear along the ray.
  std::pair<float, float> Clip(const Ray& ray, float lo, float hi) const {
    Vec3f n = Normal();
    float denom = Dot(direction, n);
    if (denom == 0) return {0, 0};
    auto keep = [&](float at0, float slope, float min, float max) {  // min <= at0 + slope u <= max
      if (slope == 0) {
        if (at0 < min || at0 > max) hi = lo;
        return;
      }
      float u0 = (min - at0) / slope, u1 = (max - at0) / slope;
      lo = std::max(lo, std::min(u0, u1));
      hi = std::min(hi, std::max(u0, u1));
    };
    // Along the ray: back-distance t(u), and the foot q(u) = x(u) - t(u) direction.
    float t0 = Dot(ray.o - corner, n) / denom, t1 = Dot(ray.d, n) / denom;
    keep(t0, t1, 0, kInfinity);
    Vec3f q0 = ray.o - t0 * direction - corner, q1 = ray.d - t1 * direction;
    float e1 = Dot(edge1, edge1), e2 = Dot(edge2, edge2);
    keep(Dot(q0, edge1) / e1, Dot(q1, edge1) / e1, 0, 1);
    keep(Dot(q0, edge2) / e2, Dot(q1, edge2) / e2, 0, 1);
    return {lo, std::max(lo, hi)};
  }
};

struct Lights {
  std::vector<PointLight> points;
  std::vector<CollimatedRect> rects;

  // Power per channel averaged: the weight for choosing a light to start a path from.
  std::vector<float> Powers() const {
    std::vector<float> p;
    for (const PointLight& l : points) p.push_back(l.SolidAngle() * l.intensity.Average());
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
  if (l.fibonacci_beams || !l.Lights(p)) return std::nullopt;  // beams are delta directions
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
