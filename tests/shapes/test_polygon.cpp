// POV-Ray's polygon (shapes/polygon): the even-odd rule over its sub-polygons, in their plane.
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/shapes/polygon.hpp"

#include "pov_scene.hpp"

using namespace rt;
using rt::test::pov;
using rt::test::povFailure;

namespace {

const Material kMaterial{};

}  // namespace

TEMPLATE_TEST_CASE("the manual's letter P is hit on its outline and not in its hole", "[polygon]", float, double) {
  using T = TestType;
  const SceneDesc s = pov(
      "polygon { 12, <0, 0>, <0, 6>, <4, 6>, <4, 3>, <1, 3>, <1,0>, <0, 0>,\n"
      "              <1, 4>, <1, 5>, <3, 5>, <3, 4>, <1, 4> }\n");
  const auto& d = std::get<PolygonDesc>(s.objects[0].shape);
  const auto p = d.make<T>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
  const auto at = [&](T x, T y) { return p->intersect({{x, y, -2}, {0, 0, 1}}, Interval<T>{}); };
  const auto stem = at(T(0.5), T(1));
  REQUIRE(stem);
  CHECK(stem->t == 2);
  CHECK(stem->point == Vec3<T>(T(0.5), 1, 0));
  CHECK(std::abs(stem->normal.z) == 1);
  CHECK(at(T(3.5), T(5.5)));             // the bowl, above the hole
  CHECK_FALSE(at(2, 4.5));               // the hole
  CHECK_FALSE(at(2, 1));                 // right of the stem, under the bowl
  CHECK_FALSE(at(T(4.5), T(5)));         // past the outline
  CHECK_FALSE(p->intersect({{0.5, 1, -2}, {1, 0, 0}}, Interval<T>{}));  // along its plane
  CHECK_FALSE(p->inside({T(0.5), 1, 0}));
  const auto box = p->bounds();
  REQUIRE(box);
  CHECK(box->min == Vec3<T>(0, 0, 0));
  CHECK(box->max == Vec3<T>(4, 6, 0));
}

TEST_CASE("a polygon left open is closed, in any plane", "[polygon]") {
  const SceneDesc s = pov("polygon { 3, <0, 0, 0>, <0, 2, 0>, <0, 0, 2> }\n");
  const auto p =
      std::get<PolygonDesc>(s.objects[0].shape).make<double>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
  const auto hit = p->intersect({{3, 0.5, 0.5}, {-1, 0, 0}}, Interval<double>{});
  REQUIRE(hit);
  CHECK(hit->t == 3);
  CHECK(std::abs(hit->normal.x) == 1);
  CHECK_FALSE(p->intersect({{3, 1.5, 1.5}, {-1, 0, 0}}, Interval<double>{}));
}

TEST_CASE("a polygon of too few points, or out of one plane, is an error where it is written", "[polygon]") {
  CHECK(povFailure("polygon { 2, <0, 0>, <1, 1> }\n") ==
        "scene.pov:2:11: error: a polygon needs a whole number of points, at least 3, found 2");
  CHECK(povFailure("polygon { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 1> }\n") ==
        "scene.pov:2:11: error: the polygon's points are not in one plane");
  CHECK(povFailure("polygon { 3, <0, 0>, <1, 1>, <2, 2> }\n") ==
        "scene.pov:2:11: error: the polygon's points span no plane");
  CHECK(povFailure("polygon { 4, <0, 0>, <1, 1>, <2, 2> }\n") ==
        "scene.pov:2:1: error: 'polygon' needs a polygon point");
}

TEST_CASE("the course subset reads a polygon, its commas required", "[polygon]") {
  const SceneDesc s = parsePov(
      "camera { location <0,0,5> look_at <0,0,0> }\npolygon { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,0,0> }\n", "s.pov");
  REQUIRE(s.objects.size() == 1);
  CHECK(std::get<PolygonDesc>(s.objects[0].shape).points.size() == 4);
  std::string message;
  try {
    parsePov("camera { location <0,0,5> look_at <0,0,0> }\npolygon { 3 <0,0,0>, <1,0,0>, <1,1,0> }\n", "s.pov");
  } catch (const Error& e) {
    message = e.what();
  }
  CHECK(message == "s.pov:2:13: error: expected ',' after the number of polygon points, found '<'");
}
