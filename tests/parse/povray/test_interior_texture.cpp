// interior_texture: the texture a hit sees from inside the surface (the POV-Ray 3.7 manual, "Interior Texture").
#include <catch2/catch.hpp>

#include "pov_scene.hpp"
#include "raytrace/shapes/make_object.hpp"

namespace rt {
namespace {

// The pigment and the shading normal a ray along +z from (0, 0, z) sees on the object's first hit.
std::pair<Color, glm::dvec3> seen(const Object<double>& object, double z) {
  const Ray<double> ray{{0, 0, z}, {0, 0, 1}};
  const auto hit = object.intersect(ray, {});
  REQUIRE(hit);
  glm::dvec3 n = glm::dot(ray.dir, hit->normal) <= 0 ? hit->normal : -hit->normal;
  Material scratch;
  const Color pigment = object.materialAt(*hit, scratch, n).pigment;
  return {pigment, n};
}

TEST_CASE("interior_texture: the outside keeps the texture, the inside sees the interior one", "[povray][interior_texture]") {
  const SceneDesc s = test::pov(R"(
sphere { 0, 1 texture { pigment { rgb <0, 0, 1> } } interior_texture { pigment { rgb <1, 0.5, 0> } } }
)");
  REQUIRE(s.objects.size() == 1);
  REQUIRE(s.objects[0].texture);  // a constant texture too, so that the inside can differ
  const auto object = makeObject<double>(s.objects[0], SphereMethod::Auto, 1, false);
  CHECK(seen(*object, -5).first == Color(0, 0, 1));
  CHECK(seen(*object, 0).first == Color(1, 0.5f, 0));
  // Its bound covers both, for the tracer's cut-off.
  CHECK(s.objects[0].texture->bound.pigment == Color(1, 0.5f, 1));
}

TEST_CASE("interior_texture: its normal bends the inside only, and it moves with the object", "[povray][interior_texture]") {
  const SceneDesc s = test::pov(R"(
sphere { 0, 1 pigment { rgb 1 } interior_texture { pigment { gradient z color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 1, 0>] } scale 4 } normal { bumps 1 scale 0.1 } } translate <0, 0, 10> }
)");
  const auto object = makeObject<double>(s.objects[0], SphereMethod::Auto, 1, false);
  const auto [outside, outsideNormal] = seen(*object, 0);
  CHECK(outside == Color(1));
  CHECK(outsideNormal == glm::dvec3(0, 0, -1));
  // From the centre the ray meets (0, 0, 11), the unmoved sphere's (0, 0, 1): a quarter of the way up the map.
  const auto [inside, insideNormal] = seen(*object, 10);
  CHECK(inside.r == Approx(0.75));
  CHECK(inside.g == Approx(0.25));
  CHECK(insideNormal != glm::dvec3(0, 0, -1));
}

TEST_CASE("interior_texture: a refused item in it is refused", "[povray][interior_texture]") {
  CHECK(test::povFailure("sphere { 0, 1 interior_texture { pigment { rgb 1 } finish { reflection { 0.3 exponent 2 } } } }") ==
        "scene.pov:2:78: error: 'exponent' is not supported yet");
}

}  // namespace
}  // namespace rt
