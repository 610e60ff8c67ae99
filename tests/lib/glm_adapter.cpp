// The optional GLM adapter (vrlis/glm.hpp) builds the same queries as the core builders from
// unnormalised GLM directions; a wrong field or a missing normalisation fails here.
#include <catch2/catch.hpp>
#include <cmath>

#include <vrlis/glm.hpp>

namespace {

bool Same(vrlis::Vec3<float> a, vrlis::Vec3<float> b) {
  return std::abs(a.x - b.x) <= 1e-6f && std::abs(a.y - b.y) <= 1e-6f && std::abs(a.z - b.z) <= 1e-6f;
}

void RequireSame(const vrlis::SegmentQuery<float>& a, const vrlis::SegmentQuery<float>& b) {
  CHECK(Same(a.origin, b.origin));
  CHECK(Same(a.dir, b.dir));
  CHECK(a.tmin == b.tmin);
  CHECK(a.tmax == b.tmax);
  CHECK(a.g == b.g);
  CHECK(Same(a.point, b.point));
  CHECK(a.lobe.kind == b.lobe.kind);
  CHECK(Same(a.lobe.axis, b.lobe.axis));
  CHECK(a.lobe.g == b.lobe.g);
  CHECK(a.sigma_t == b.sigma_t);
}

}  // namespace

TEST_CASE("the GLM adapter builds the core builders' queries, directions normalised", "[glm]") {
  const glm::vec3 o(0.5f, -1, 2), d(0, 3, 4), p(1, 2, -0.5f), w(-2, 0, 0);
  const vrlis::Vec3<float> dn{0, 0.6f, 0.8f}, wn{-1, 0, 0};
  RequireSame(vrlis::MediumQuery(o, d, 0.25f, 7.f, p, w, 0.7f, 0.3f),
              vrlis::MediumToMediumQuery(vrlis::FromXyz(o), dn, 0.25f, 7.f, vrlis::FromXyz(p), wn, 0.7f, 0.3f));
  RequireSame(vrlis::SurfaceQuery(o, d, 0.f, 5.f, p, w, -0.4f, 0.2f),
              vrlis::MediumToSurfaceQuery(vrlis::FromXyz(o), dn, 0.f, 5.f, vrlis::FromXyz(p), wn, -0.4f, 0.2f));
  CHECK(vrlis::SurfaceQuery(o, d, 0.f, 5.f, p, w, -0.4f, 0.2f).lobe.kind == vrlis::LobeKind::ClampedCosine);
  CHECK(vrlis::MediumQuery(o, d, 0.25f, 7.f, p, w, 0.7f).lobe.kind == vrlis::LobeKind::HenyeyGreenstein);

  const vrlis::VrlPointQuery<float> v = vrlis::VrlPointQueryFor(o, d, 3.f, p, w);
  CHECK(Same(v.origin, vrlis::FromXyz(o)));
  CHECK(Same(v.dir, dn));
  CHECK(v.tmin == 0.f);
  CHECK(v.tmax == 3.f);
  CHECK(Same(v.line_origin, vrlis::FromXyz(p)));
  CHECK(Same(v.line_dir, wn));
}
