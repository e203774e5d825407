// `texture { average texture_map { [w T] … } }`: every texture at once, its colour terms weighted by w over the
// weights' sum (the POV-Ray 3.7 manual, "Average"); an entry without its weight counts 1.
#include <catch2/catch.hpp>

#include "pov_scene.hpp"
#include "raytrace/surface/texture.hpp"

namespace rt {
namespace {

TEST_CASE("average texture: the colour terms weighted, the highlight's shape from the one that has one",
          "[povray][average_texture]") {
  const SceneDesc s = test::pov(R"(
plane { y, 0 texture { average texture_map {
  [3 pigment { rgb <1, 0, 0> } finish { ambient 0.2 diffuse 0.8 }]
  [1 pigment { rgb <0, 0, 1> } finish { ambient 0.2 diffuse 0.4 phong 1 phong_size 20 }]
} } }
plane { y, 0 texture { average texture_map {
  [pigment { rgb <1, 0, 0> }]
  [pigment { rgb <0, 1, 0> }]
} } }
)");
  REQUIRE(s.objects.size() == 2);
  const Material m = s.objects[0].texture->at({0.3, 0, 0.7});
  CHECK(m.pigment == Color(0.75f, 0, 0.25f));
  CHECK(m.ambient.r == Approx(0.15));
  CHECK(m.ambient.b == Approx(0.05));
  CHECK(m.diffuse.r == Approx(0.6));
  CHECK(m.diffuse.b == Approx(0.1));
  CHECK(m.specular.r == Approx(0.25));
  CHECK(m.exponent == 20);
  CHECK(m.lobe == Material::Lobe::Mirror);
  CHECK(s.objects[1].texture->at({0, 0, 0}).pigment == Color(0.5f, 0.5f, 0));
}

TEST_CASE("average texture: with a pattern or without weights it stops", "[povray][average_texture]") {
  CHECK(test::povFailure("plane { y, 0 texture { average checker texture_map { [1 pigment { rgb 1 }] } } }") ==
        "scene.pov:2:14: error: 'average' takes no pattern");
  CHECK(test::povFailure("plane { y, 0 texture { average texture_map { [0 pigment { rgb 1 }] } } }") ==
        "scene.pov:2:14: error: an average's weights must add up to more than 0");
  CHECK(test::povFailure("plane { y, 0 texture { gradient x texture_map { [pigment { rgb 1 }] } } }") ==
        "scene.pov:2:49: error: a texture_map entry needs its value before its texture");
}

}  // namespace
}  // namespace rt
