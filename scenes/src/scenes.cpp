#include "vrlis_scenes/scenes.hpp"

#include <memory>

#include "embree_geometry.hpp"

namespace vrlis::scenes {
namespace {

using vrlis::integration::Material;
using vrlis::integration::MaterialKind;
using vrlis::integration::Spectrum;
using vrlis::integration::Vec3f;

int AddMaterial(vrlis::integration::Scene& s, Material m) {
  s.materials.push_back(m);
  return static_cast<int>(s.materials.size()) - 1;
}
int Diffuse(vrlis::integration::Scene& s, Spectrum albedo) { return AddMaterial(s, {MaterialKind::Diffuse, albedo, 1.5f}); }

// An axis-aligned room [lo, hi] seen from inside, with its own material per wall.
void AddRoom(EmbreeGeometry& g, Vec3f lo, Vec3f hi, int left, int right, int floor, int ceiling, int back,
             int front) {
  auto c = [&](int x, int y, int z) { return Vec3f{x ? hi.x : lo.x, y ? hi.y : lo.y, z ? hi.z : lo.z}; };
  g.AddQuad(c(0, 0, 0), c(0, 1, 0), c(0, 1, 1), c(0, 0, 1), left);
  g.AddQuad(c(1, 0, 0), c(1, 0, 1), c(1, 1, 1), c(1, 1, 0), right);
  g.AddQuad(c(0, 0, 0), c(0, 0, 1), c(1, 0, 1), c(1, 0, 0), floor);
  g.AddQuad(c(0, 1, 0), c(1, 1, 0), c(1, 1, 1), c(0, 1, 1), ceiling);
  g.AddQuad(c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 1, 0), back);
  g.AddQuad(c(0, 0, 1), c(0, 1, 1), c(1, 1, 1), c(1, 0, 1), front);
}

void Bidirectional(BuiltScene& b, EmbreeGeometry&) {
  b.scene.medium = {0.25f, 0.1f, -0.9f};
  b.scene.lights.points.push_back({{0, 0, -2}, Spectrum(2.f), true});
  b.transport.first_segment_only = true;
  b.transport.medium_to_surface = b.transport.direct = b.transport.indirect = false;
  b.transport.surface_to_surface = b.transport.surface_to_medium = false;
}

// The room of the room and fog scenes with its lower box: side walls `left` and `right`,
// the rest `other`.
void AddRoomAndBox(EmbreeGeometry& g, int left, int right, int other) {
  AddRoom(g, {-2.55f, -2.5f, -4.5f}, {2.55f, 2.5f, 0.5f}, left, right, other, other, other, other);
  g.AddBox({0.25f, -2.5f, -3.75f}, {1.75f, -1, -2.75f}, other);
}

void Room(BuiltScene& b, EmbreeGeometry& g) {
  vrlis::integration::Scene& s = b.scene;
  int grey = Diffuse(s, Spectrum(0.5f));
  int orange = Diffuse(s, {1, 0.5f, 0}), cyan = Diffuse(s, {0, 1, 1});
  AddRoomAndBox(g, orange, cyan, grey);
  g.AddBox({-1.75f, -2.5f, -4.5f}, {-0.25f, 0.5f, -3.75f}, grey);
  s.medium = {0.01f, 0.1f, 0.5f};
  Vec3f dir = vrlis::integration::Normalize(Vec3f{-0.1f, -1, 0.075f});
  for (auto [x0, x1] : {std::pair{-0.65f, -0.495f}, {-0.425f, -0.27f}, {-0.2f, -0.045f}, {0.025f, 0.18f}})
    s.lights.rects.push_back({{x0, 2.5f, -3.5f}, {x1 - x0, 0, 0}, {0, 0, 0.32f}, dir, Spectrum(20.f)});
}

void Cube(BuiltScene& b, EmbreeGeometry& g) {
  vrlis::integration::Scene& s = b.scene;
  int grey = Diffuse(s, Spectrum(0.5f));
  int red = Diffuse(s, {0.75f, 0.1f, 0.1f}), green = Diffuse(s, {0.1f, 0.75f, 0.1f});
  AddRoom(g, {-2.75f, -2.5f, -5.5f}, {2.75f, 3.0f, 0.5f}, red, green, grey, grey, grey, grey);
  g.AddSphere({-0.75f, -1.45f, -4.4f}, 1.05f, AddMaterial(s, {MaterialKind::Mirror, Spectrum(0.95f), 1.5f}));
  g.AddSphere({2.0f, -2.05f, -3.7f}, 0.5f, AddMaterial(s, {MaterialKind::Glass, Spectrum(1.f), 1.5f}));
  g.AddSphere({-1.75f, -1.95f, -3.1f}, 0.6f, Diffuse(s, {0, 0, 1}));
  s.medium = {0.1f, 0.5f, 0.5f};
  s.medium.shape = vrlis::integration::HomogeneousMedium::Shape::Box;
  s.medium.lo = {-0.75f, -1.75f, -3.75f};
  s.medium.hi = {0.75f, -0.25f, -2.25f};
  s.lights.points.push_back({{0, 1.9f, -3}, Spectrum(6.f), false});
}

void Corner(BuiltScene& b, EmbreeGeometry& g) {
  vrlis::integration::Scene& s = b.scene;
  // VRLs pass within a few mean free paths of the camera's surfaces and segments, where the
  // gathers' 1 / r^2 gives rare large samples: the remainder takes connections closer than 1.
  b.transport.vrl_bound = 1;
  int grey = Diffuse(s, Spectrum(0.5f));
  struct Plane {
    Vec3f n;
    float d;
    int material;
  };
  const Plane planes[] = {
      {{0.973562f, -0.226953f, -0.025893f}, 5.2f, Diffuse(s, {1, 0.506f, 0})},
      {{-0.973562f, 0.226953f, 0.025893f}, 0.3f, Diffuse(s, {0, 0.949f, 1})},
      {{-0.105381f, 0.974352f, 0.198829f}, 0.4f, grey},
      {{0.105381f, -0.974352f, -0.198829f}, 5.1f, grey},
      {{-0.122788f, 0.007596f, 0.992404f}, 1.5f, grey},
      {{0.122788f, -0.007596f, -0.992404f}, 4.0f, grey},
  };
  for (const Plane& p : planes) {  // n . x + d = 0 as a large quad: rays stay inside
    vrlis::integration::Frame f(vrlis::integration::Normalize(p.n));
    Vec3f c = (-p.d) * p.n;
    const float r = 40;
    g.AddQuad(c + r * (f.x + f.y), c + r * (f.y - f.x), c - r * (f.x + f.y), c + r * (f.x - f.y), p.material);
  }
  g.AddSphere({0, 0, -0.8f}, 0.25f, Diffuse(s, Spectrum(0.9f)));
  s.medium = {0.5f, 0.65f, 0.5f};
  s.lights.points.push_back({{-2.45f, 2.35f, 1.25f}, Spectrum(60.f), false});
  s.camera.fov_x = vrlis::integration::kPi / 3;
}

// A dense, bright cloud over a floor under a spot light: multiple scattering carries its light
// (several mean free paths thick, albedo 0.95), and the floor receives its shadow and glow.
void Cloud(BuiltScene& b, EmbreeGeometry& g) {
  vrlis::integration::Scene& s = b.scene;
  // Inside the small cloud the gathers' 1 / r^2 between close VRL and camera points holds
  // most of the image's variance: with the remainder taking connections closer than 1 the
  // renderer beats its own path tracer (docs/renderer.md#bound-choice), unbounded it loses.
  b.transport.vrl_bound = 1;
  int grey = Diffuse(s, Spectrum(0.5f));
  g.AddQuad({-8, -1.5f, 1}, {8, -1.5f, 1}, {8, -1.5f, -12}, {-8, -1.5f, -12}, grey);  // the floor
  s.medium = {2.0f, 0.1f, 0.7f};
  s.medium.shape = vrlis::integration::HomogeneousMedium::Shape::Sphere;
  s.medium.center = {0, 0.3f, -3.6f};
  s.medium.radius = 1.1f;
  vrlis::integration::PointLight spot{{2.5f, 3.0f, -2.0f}, Spectrum(20.f), false};
  spot.axis = vrlis::integration::Normalize(s.medium.center - spot.position);
  spot.cos_cone = std::cos(25 * vrlis::integration::kPi / 180);  // the cloud and a pool of floor around it
  s.lights.points.push_back(spot);
}

// The room filled with fog that scatters, lit through one window by a collimated beam: the
// god ray and the glow around it come from light scattered many times.
void Fog(BuiltScene& b, EmbreeGeometry& g) {
  vrlis::integration::Scene& s = b.scene;
  // Dark walls, as in a hall: the light the fog sends on is the fog's.
  int dark = Diffuse(s, Spectrum(0.15f));
  int orange = Diffuse(s, {0.3f, 0.15f, 0}), cyan = Diffuse(s, {0, 0.3f, 0.3f});
  AddRoomAndBox(g, orange, cyan, dark);
  s.medium = {0.8f, 0.04f, 0.7f};
  Vec3f dir = vrlis::integration::Normalize(Vec3f{1, -0.7f, 0.15f});
  s.lights.rects.push_back({{-2.55f, 0.6f, -3.6f}, {0, 1.2f, 0}, {0, 0, 1.4f}, dir, Spectrum(10.f)});
}

}  // namespace

std::optional<BuiltScene> BuildScene(std::string_view name, const MediumOverrides& o) {
  using Builder = void (*)(BuiltScene&, EmbreeGeometry&);
  Builder builder = name == "bidirectional" ? Bidirectional
                    : name == "room"        ? Room
                    : name == "cube"        ? Cube
                    : name == "corner"      ? Corner
                    : name == "cloud"       ? Cloud
                    : name == "fog"         ? Fog
                                            : nullptr;
  if (!builder) return std::nullopt;
  auto geometry = std::make_shared<EmbreeGeometry>();
  BuiltScene b;
  builder(b, *geometry);
  geometry->Commit();
  b.has_surfaces = !geometry->Empty();
  b.scene.geometry = geometry;
  vrlis::integration::HomogeneousMedium& m = b.scene.medium;
  if (o.g) m.g = *o.g;
  if (o.sigma_s) m.sigma_s = *o.sigma_s;
  if (o.sigma_a) m.sigma_a = *o.sigma_a;
  // Rays in a medium that fills space stop at optical depth 14 (transmittance 8e-7): where no
  // surface ends them, and where one is missed through a crack between two of its triangles.
  if (!m.Bounded()) m.max_distance = m.SigmaT() > 0 ? 14.f / m.SigmaT() : 100.f;
  return b;
}

}  // namespace vrlis::scenes
