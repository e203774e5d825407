// A POV-Ray light's strength over the scene, against the factors real POV-Ray 3.7 lit a white plane with
// (read back from its pictures: a light 1 above the plane, the plane's n·l divided out).
#include <catch2/catch.hpp>

#include <cmath>

#include "raytrace/scene/light_shape.hpp"

namespace rt {
namespace {

// The factor at the point of the plane y = 0 at angle `degrees` from the light's axis (straight down).
float spotAt(const LightShape& s, double degrees) {
  const double a = glm::radians(degrees);
  return s.at(glm::dvec3(std::sin(a), -std::cos(a), 0), 1 / std::cos(a));
}

LightDesc spotlight(double radius, double falloff, double tightness) {
  LightDesc l;
  l.position = {0, 1, 0};
  l.spot = SpotDesc{{0, 0, 0}, radius, falloff, tightness};
  return l;
}

TEST_CASE("light shape: a spotlight's cone, its smooth edge and its tightness, as POV-Ray lights", "[light]") {
  // POV-Ray: radius 20, falloff 40, tightness 0.
  const LightShape edge(spotlight(20, 40, 0));
  CHECK(spotAt(edge, 10) == 1);
  CHECK(spotAt(edge, 26.51) == Approx(0.833).margin(0.003));
  CHECK(spotAt(edge, 30.05) == Approx(0.609).margin(0.003));
  CHECK(spotAt(edge, 33.36) == Approx(0.3493).margin(0.003));
  CHECK(spotAt(edge, 37.88) == Approx(0.0484).margin(0.003));
  CHECK(spotAt(edge, 41) == 0);
  // POV-Ray: radius 20, falloff 40, tightness 10.
  const LightShape tight(spotlight(20, 40, 10));
  CHECK(spotAt(tight, 9.1) == Approx(0.8825).margin(0.004));
  CHECK(spotAt(tight, 25.6) == Approx(0.3141).margin(0.004));
  // POV-Ray's defaults: radius 30, falloff 45, tightness 0.
  LightDesc defaults;
  defaults.position = {0, 1, 0};
  defaults.spot.emplace();
  CHECK(spotAt(LightShape(defaults), 25.59) == 1);
  CHECK(spotAt(LightShape(defaults), 38.59) == Approx(0.456).margin(0.004));
}

TEST_CASE("light shape: a cylinder light's radius and falloff are distances from its axis", "[light]") {
  LightDesc l;
  l.position = {0, 10, 0};
  l.spot = SpotDesc{{0, 0, 0}, 1, 2, 0, lightKindNamed("cylinder")};
  const LightShape s(l);
  // The point of the plane y = 0 at `x` from the axis.
  const auto at = [&](double x) {
    const glm::dvec3 d(x, -10, 0);
    return s.at(glm::normalize(d), glm::length(d));
  };
  // POV-Ray: radius 1, falloff 2, a light 10 above the plane.
  CHECK(at(0.5) == 1);
  CHECK(at(1.55) == Approx(0.428).margin(0.004));
  CHECK(at(1.85) == Approx(0.0602).margin(0.003));
  CHECK(at(1.95) == Approx(0.0071).margin(0.002));
  CHECK(at(2.05) == 0);
  CHECK(s.at(glm::dvec3(0, 1, 0), 1) == 0);  // behind the light
}

TEST_CASE("light shape: fading halves the light at its distance and follows its power", "[light]") {
  LightDesc l;
  l.fadeDistance = 0.5;
  l.fadePower = 2;
  CHECK(LightShape::needed(l));
  const LightShape fade(l);
  // POV-Ray: fade_distance 0.5, fade_power 2, at distances 1, 1.412 and 2.232.
  CHECK(fade.at(glm::dvec3(0, -1, 0), 1) == Approx(0.402).margin(0.003));
  CHECK(fade.at(glm::dvec3(0, -1, 0), 1.412) == Approx(0.2245).margin(0.003));
  CHECK(fade.at(glm::dvec3(0, -1, 0), 2.232) == Approx(0.0944).margin(0.003));
  CHECK(fade.at(glm::dvec3(0, -1, 0), 0.5) == 1);
  CHECK_FALSE(LightShape::needed(LightDesc{}));
}

}  // namespace
}  // namespace rt
