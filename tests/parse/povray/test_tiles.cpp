// The old tiles texture: checker's two blocks with the tile2 texture first, as POV-Ray draws it (its picture of
// `tiles { texture { A } tile2 texture { B } }` is the same, pixel for pixel, as that of `checker texture { B }
// texture { A }`).
#include <catch2/catch.hpp>

#include "pov_scene.hpp"
#include "raytrace/surface/texture.hpp"

namespace rt {
namespace {

TEST_CASE("tiles: tile2's texture where checker has its first, the other texture elsewhere", "[povray][tiles]") {
  const SceneDesc s = test::pov(R"(
plane { y, 0 texture { tiles { texture { pigment { rgb <1, 0, 0> } } tile2 texture { pigment { rgb <0, 0, 1> } finish { diffuse 0.5 } } } scale 2 } }
plane { y, 0 texture { checker texture { pigment { rgb <0, 0, 1> } } texture { pigment { rgb <1, 0, 0> } } scale 2 } }
)");
  REQUIRE(s.objects.size() == 2);
  const Texture& tiles = *s.objects[0].texture;
  const Texture& checker = *s.objects[1].texture;
  for (const glm::dvec3& p : {glm::dvec3(1, 0, 1), glm::dvec3(3, 0, 1), glm::dvec3(-1, 0, 1), glm::dvec3(3, 0, 3)}) {
    INFO(p.x << ", " << p.z);
    CHECK(tiles.at(p).pigment == checker.at(p).pigment);
  }
  CHECK(tiles.at({1, 0, 1}).pigment == Color(0, 0, 1));
  CHECK(tiles.at({1, 0, 1}).diffuse == Color(0, 0, 0.5f));
  CHECK(tiles.at({3, 0, 1}).pigment == Color(1, 0, 0));
}

TEST_CASE("tiles: without tile2 the scene stops; layered tiles are refused", "[povray][tiles]") {
  CHECK(test::povFailure("plane { y, 0 texture { tiles { texture { pigment { rgb 1 } } } } }") ==
        "scene.pov:2:24: error: tiles needs 'texture { … } tile2 texture { … }'");
  CHECK(test::povFailure("plane { y, 0 texture { tiles { texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } } "
                         "tile2 texture { pigment { rgb 0 } } } } }") ==
        "scene.pov:2:24: error: 'tiles of layered textures' is not supported yet");
}

}  // namespace
}  // namespace rt
