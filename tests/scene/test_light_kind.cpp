// The emitter kinds' table: each row is found by its POV-Ray keyword and shapes a light through its own factor.
#include <catch2/catch.hpp>

#include "raytrace/scene/light_kind.hpp"

namespace rt {
namespace {

TEST_CASE("light kinds: a kind is found by its keyword; parallel and area_light are modifiers, not kinds", "[light]") {
  REQUIRE(lightKindNamed("spotlight") == &spotlightKind());
  REQUIRE(lightKindNamed("cylinder"));
  CHECK(lightKindNamed("cylinder")->defaultRadius == 0.75);
  CHECK(lightKindNamed("cylinder")->defaultFalloff == 1);
  CHECK_FALSE(lightKindNamed("cylinder")->tightness);
  CHECK(spotlightKind().defaultRadius == 30);
  CHECK(spotlightKind().defaultFalloff == 45);
  CHECK(spotlightKind().tightness);
  CHECK(lightKindNamed("parallel") == nullptr);
  CHECK(lightKindNamed("area_light") == nullptr);
}

TEST_CASE("light kinds: a spotlight's preparation turns its degrees into cosines; a cylinder's keeps its lengths",
          "[light]") {
  Emitter spot;
  spot.radius = 60;
  spot.falloff = 90;
  spotlightKind().prepare(spot);
  CHECK(spot.radius == Approx(0.5));
  CHECK(spot.falloff == Approx(0).margin(1e-15));
  // Straight down the axis: full; across it, at the falloff cone: none.
  CHECK(spotlightKind().factor(spot, {0, -1, 0}, 1) == 1);
  CHECK(spotlightKind().factor(spot, {1, 0, 0}, 1) == 0);

  const LightKind& cylinder = *lightKindNamed("cylinder");
  Emitter tube;
  tube.radius = 1;
  tube.falloff = 3;
  cylinder.prepare(tube);
  CHECK(tube.radius == 1);
  CHECK(tube.falloff == 3);
  // 2 from the axis, halfway across the fringe: the smoothstep's ½. Behind the light: none.
  const glm::dvec3 toPoint = glm::normalize(glm::dvec3(2, -4, 0));
  CHECK(cylinder.factor(tube, toPoint, glm::length(glm::dvec3(2, -4, 0))) == Approx(0.5));
  CHECK(cylinder.factor(tube, {0, 1, 0}, 1) == 0);
}

}  // namespace
}  // namespace rt
