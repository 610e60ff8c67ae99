// The x, y, z adapter (vrlis/xyz.hpp) converts a renderer's own vectors both ways, whatever
// their shape (an aggregate, a class with a constructor, GLM's) and precision; a swapped or
// dropped component fails here.
#include <catch2/catch.hpp>
#include <glm/vec3.hpp>
#include <vrlis/xyz.hpp>

#include <type_traits>

namespace {

struct Aggregate {
  double x, y, z;
};
class WithConstructor {
 public:
  WithConstructor(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
  float x, y, z;
};
struct NotAVector {
  float a, b, c;
};

}  // namespace

TEST_CASE("any vector with x, y, z converts to Vec3 and back", "[xyz]") {
  static_assert(vrlis::HasXyz<Aggregate>::value && vrlis::HasXyz<WithConstructor>::value && vrlis::HasXyz<glm::vec3>::value);
  static_assert(!vrlis::HasXyz<NotAVector>::value && !vrlis::HasXyz<float>::value);

  const Aggregate a{1.5, -2.25, 3.125};
  const auto deduced = vrlis::FromXyz(a);
  static_assert(std::is_same_v<decltype(deduced), const vrlis::Vec3<double>>);
  CHECK((deduced.x == 1.5 && deduced.y == -2.25 && deduced.z == 3.125));
  const vrlis::Vec3<float> f = vrlis::FromXyz<float>(a);
  CHECK((f.x == 1.5f && f.y == -2.25f && f.z == 3.125f));

  const auto back = vrlis::ToXyz<Aggregate>(f);
  CHECK((back.x == 1.5 && back.y == -2.25 && back.z == 3.125));
  const auto constructed = vrlis::ToXyz<WithConstructor>(vrlis::Vec3<double>{4, 5, 6});
  CHECK((constructed.x == 4 && constructed.y == 5 && constructed.z == 6));
  const glm::vec3 g = vrlis::ToXyz<glm::vec3>(vrlis::FromXyz(constructed));
  CHECK((g.x == 4 && g.y == 5 && g.z == 6));
}
