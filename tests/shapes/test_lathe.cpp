// The lathe: a vertical segment turned about y is a tube; closed profiles keep inside() and the crossings of random
// rays in step, for every spline.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <string>

#include "crossing_parity.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/shapes/lathe.hpp"

using namespace rt;

namespace {

const Material kMaterial{};

std::unique_ptr<Object<double>> lathe(SplineKind spline, const std::vector<glm::dvec2>& points, bool sturm = false) {
  return LatheDesc{spline, points, sturm}.make<double>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
}

std::optional<Hit<double>> shoot(const Object<double>& o, const glm::dvec3& origin, const glm::dvec3& dir) {
  return o.intersect(Ray<double>{origin, glm::normalize(dir)}, Interval<double>{});
}

std::string povFailure(const std::string& body) {
  try {
    povray::parsePovRay("#version 3.7;\n" + body, "scene.pov", povray::PovRayOptions{{}, 320, 240, false});
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("lathe: a linear lathe of a vertical segment is a cylinder's side", "[lathe]") {
  for (const bool sturm : {false, true}) {
    const auto tube = lathe(SplineKind::Linear, {{1, 0}, {1, 2}}, sturm);
    const auto in = shoot(*tube, {-5, 1, 0}, {1, 0, 0});
    REQUIRE(in);
    CHECK(in->t == Approx(4));
    CHECK(in->normal.x == Approx(-1));
    // From the axis, inside by the even-odd rule, the wall is met with its normal outward.
    const auto out = shoot(*tube, {0, 1, 0}, {0, 0, 1});
    REQUIRE(out);
    CHECK(out->t == Approx(1));
    CHECK(out->normal.z == Approx(1));
    // Slanted, and level to the last bit: both formulations give the cylinder's t.
    const auto slant = shoot(*tube, {-5, 0, 0.6}, {1, 0.1, 0});
    REQUIRE(slant);
    CHECK(slant->point.x == Approx(-0.8));
    const auto level = shoot(*tube, {-5, 1, 0.6}, {1, 1e-12, 0});
    REQUIRE(level);
    CHECK(level->t == Approx(4.2));
    CHECK_FALSE(shoot(*tube, {0.3, 5, 0}, {0, -1, 0}));  // no caps
    CHECK(tube->inside(Vec3<double>(0.5, 1, 0.5)));
    CHECK_FALSE(tube->inside(Vec3<double>(0.5, 3, 0.5)));
  }
}

TEST_CASE("lathe: the manual's thick cylinder has its rims, walls and hole", "[lathe]") {
  const auto thick = lathe(SplineKind::Linear, {{2, 0}, {3, 0}, {3, 5}, {2, 5}, {2, 0}});
  const auto top = shoot(*thick, {2.5, 10, 0}, {0, -1, 0});
  REQUIRE(top);
  CHECK(top->t == Approx(5));
  CHECK(top->normal.y == Approx(1));
  const auto side = shoot(*thick, {-10, 2.5, 0}, {1, 0, 0});
  REQUIRE(side);
  CHECK(side->t == Approx(7));
  CHECK(side->normal.x == Approx(-1));
  const auto inner = thick->intersect(Ray<double>{{-10, 2.5, 0}, {1, 0, 0}}, Interval<double>{7.5, 100});
  REQUIRE(inner);
  CHECK(inner->t == Approx(8));
  CHECK(inner->normal.x == Approx(1));
  CHECK_FALSE(thick->inside(Vec3<double>(0, 2.5, 0)));
  const auto bounds = *thick->bounds();
  CHECK(bounds.min == glm::dvec3(-3, 0, -3));
  CHECK(bounds.max == glm::dvec3(3, 5, 3));
}

TEST_CASE("lathe: random rays cross closed profiles of every spline as inside() says", "[lathe]") {
  const std::vector<glm::dvec2> loop{{2, 0}, {3, 0}, {3, 5}, {2, 5}, {2, 0}};
  CHECK(test::parityMismatches(*lathe(SplineKind::Linear, loop), {-3, 0, -3}, {3, 5, 3}, 21) == 0);
  // Closed as the manual says: quadratic P[n-1] = P[1]; cubic P[n-1] = P[2], P[n] = P[3], P[n-2] = P[1].
  const std::vector<glm::dvec2> quadratic{{1, 0}, {3, 1}, {2, 3}, {1, 0}, {3, 1}};
  CHECK(test::parityMismatches(*lathe(SplineKind::Quadratic, quadratic), {-4, -1, -4}, {4, 4, 4}, 22) == 0);
  const std::vector<glm::dvec2> cubic{{1, 2}, {1, 0}, {3, 1}, {2, 3}, {1, 2}, {1, 0}, {3, 1}};
  CHECK(test::parityMismatches(*lathe(SplineKind::Cubic, cubic, true), {-4, -1, -4}, {4, 4, 4}, 23) == 0);
  const std::vector<glm::dvec2> bezier{{1, 0}, {2, -1}, {3, 1}, {3, 2}, {3, 2}, {3, 4}, {1, 4}, {1, 0}};
  CHECK(test::parityMismatches(*lathe(SplineKind::Bezier, bezier), {-4, -1, -4}, {4, 4, 4}, 24) == 0);
}

TEST_CASE("lathe: bad input stops at the number of points, with what is wrong", "[lathe]") {
  CHECK(povFailure("lathe { 1, <1, 0> }") ==
        "scene.pov:2:9: error: a linear_spline lathe needs at least 2 points, found 1");
  CHECK(povFailure("lathe { cubic_spline 3, <1, 0>, <1, 1>, <1, 2> }") ==
        "scene.pov:2:22: error: a cubic_spline lathe needs at least 4 points, found 3");
  CHECK(povFailure("lathe { bezier_spline 5, <1, 0>, <1, 1>, <1, 2>, <1, 3>, <1, 4> }") ==
        "scene.pov:2:23: error: a bezier_spline lathe needs a multiple of 4 points, found 5");
  CHECK(povFailure("lathe { 3, <1, 0>, <1, 1> pigment { rgb 1 } }") ==
        "scene.pov:2:27: error: 'lathe' needs a lathe point");
  CHECK(povFailure("lathe { 2, <1, 0>, <1, 1>, <1, 2> pigment { rgb 1 } }") ==
        "scene.pov:2:28: error: more lathe points than the 2 its count gives");
}

TEST_CASE("lathe: a segment's ring passes over only the rays that cannot meet it", "[lathe]") {
  const Ring ring{0, 1, 1, 4};  // heights 0 to 1, radii 1 to 2 (squared: 1 to 4)
  CHECK_FALSE(ring.missedBy({3, 0.5, 0}, {-1, 0, 0}, 0, 10));  // level, through the wall toward the axis
  CHECK(ring.missedBy({3, 2, 0}, {-1, 0, 0}, 0, 10));          // level, above it
  CHECK(ring.missedBy({0, 5, 0}, {0, -1, 0}, 0, 10));          // down the axis: always inside the hole
  CHECK(ring.missedBy({3, 5, 0}, {0, -1, 0}, 0, 10));          // down at radius 3: always outside
  CHECK_FALSE(ring.missedBy({1.5, 5, 0}, {0, -1, 0}, 0, 10));  // down through the ring
  CHECK(ring.missedBy({3, 0.5, 0}, {-1, 0, 0}, 0, 0.5));       // stops at radius 2.5, short of the wall
  CHECK_FALSE(ring.missedBy({3, -1, 0}, {-1, 1, 0}, 0, 10));   // climbs into it from below
}
