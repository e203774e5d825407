// The prism: a square one is a box; a frame's hole and a curved outline keep inside() and the crossings in step.
#include <catch2/catch.hpp>
#include <memory>
#include <string>

#include "crossing_parity.hpp"
#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/shapes/prism.hpp"

using namespace rt;

namespace {

const Material kMaterial{};

std::unique_ptr<Object<double>> prism(SplineKind spline, bool conic, double h1, double h2,
                                      const std::vector<glm::dvec2>& points, bool open = false) {
  PrismDesc d;
  d.spline = spline;
  d.conic = conic;
  d.height1 = h1;
  d.height2 = h2;
  d.points = points;
  d.outline = PrismDesc::prismOutline(spline, points, SourceLoc{});
  d.open = open;
  return d.make<double>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
}

const std::vector<glm::dvec2> kSquare{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};

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

TEST_CASE("prism: a square linear prism is the box it sweeps, walls and caps", "[prism]") {
  const auto box = prism(SplineKind::Linear, false, 0, 2, kSquare);
  const auto side = shoot(*box, {-5, 1, 0.3}, {1, 0, 0});
  REQUIRE(side);
  CHECK(side->t == Approx(4));
  CHECK(side->normal.x == Approx(-1));
  const auto top = shoot(*box, {0.3, 5, 0.2}, {0, -1, 0});
  REQUIRE(top);
  CHECK(top->t == Approx(3));
  CHECK(top->normal.y == Approx(1));
  const auto out = shoot(*box, {0, 1, 0}, {0, 0, 1});
  REQUIRE(out);
  CHECK(out->t == Approx(1));
  CHECK(out->normal.z == Approx(1));
  CHECK(box->inside(Vec3<double>(0.5, 1, -0.5)));
  CHECK_FALSE(box->inside(Vec3<double>(0.5, 2.5, -0.5)));
  const auto bounds = *box->bounds();
  CHECK(bounds.min == glm::dvec3(-1, 0, -1));
  CHECK(bounds.max == glm::dvec3(1, 2, 1));
  // Open: a ray down the middle meets nothing.
  CHECK_FALSE(shoot(*prism(SplineKind::Linear, false, 0, 2, kSquare, true), {0.3, 5, 0.2}, {0, -1, 0}));
}

TEST_CASE("prism: conic_sweep scales the outline by the height, to a point at the origin", "[prism]") {
  const auto pyramid = prism(SplineKind::Linear, true, 0, 1, kSquare);
  const auto side = shoot(*pyramid, {-5, 0.5, 0}, {1, 0, 0});
  REQUIRE(side);
  CHECK(side->t == Approx(4.5));
  CHECK(side->normal.x == Approx(-1 / std::sqrt(2.0)));
  CHECK(side->normal.y == Approx(-1 / std::sqrt(2.0)));  // the walls lean out as they rise
  const auto base = shoot(*pyramid, {0.9, 5, 0.9}, {0, -1, 0});
  REQUIRE(base);
  CHECK(base->t == Approx(4));
  CHECK(pyramid->inside(Vec3<double>(0.2, 0.5, 0.2)));
  CHECK_FALSE(pyramid->inside(Vec3<double>(0.6, 0.5, 0.2)));
}

TEST_CASE("prism: a frame's hole is outside; the crossings of random rays match inside()", "[prism]") {
  const std::vector<glm::dvec2> frame{{0, 0}, {6, 0}, {6, 8}, {0, 8}, {0, 0}, {1, 1}, {5, 1}, {5, 7}, {1, 7}, {1, 1}};
  const auto linear = prism(SplineKind::Linear, false, 0, 1, frame);
  CHECK_FALSE(linear->inside(Vec3<double>(3, 0.5, 4)));
  CHECK(linear->inside(Vec3<double>(0.5, 0.5, 4)));
  const auto hole = shoot(*linear, {3, 5, 4}, {0, -1, 0});
  CHECK_FALSE(hole);
  CHECK(test::parityMismatches(*linear, {0, 0, 0}, {6, 1, 8}, 11) == 0);
  // The manual's examples of the other splines.
  const std::vector<glm::dvec2> quadratic{{1, -1}, {0, 0}, {6, 0}, {6, 8}, {0, 8}, {0, 0},
                                          {2, 0},  {1, 1}, {5, 1}, {5, 7}, {1, 7}, {1, 1}};
  const std::vector<glm::dvec2> cubic{{1, -1}, {0, 0}, {6, 0}, {6, 8}, {0, 8}, {0, 0}, {-1, 1},
                                      {2, 0},  {1, 1}, {5, 1}, {5, 7}, {1, 7}, {1, 1}, {0, 2}};
  const std::vector<glm::dvec2> bezier{{0, 0}, {2, -1}, {4, 1}, {6, 0}, {6, 0}, {7, 3}, {5, 5},  {6, 8},
                                       {6, 8}, {3, 9},  {2, 7}, {0, 8}, {0, 8}, {1, 5}, {-1, 3}, {0, 0}};
  CHECK(test::parityMismatches(*prism(SplineKind::Quadratic, false, 0, 1, quadratic), {-1, 0, -1}, {7, 1, 9}, 12) == 0);
  CHECK(test::parityMismatches(*prism(SplineKind::Cubic, false, 0, 1, cubic), {-1, 0, -1}, {7, 1, 9}, 13) == 0);
  CHECK(test::parityMismatches(*prism(SplineKind::Bezier, true, 0.5, 1, bezier), {-1, 0, -1}, {8, 1, 9}, 14) == 0);
}

TEST_CASE("prism: bad input stops at the number of points, with what is wrong", "[prism]") {
  CHECK(povFailure("prism { 0, 1, 2, <0, 0>, <1, 0> }") ==
        "scene.pov:2:15: error: a linear_spline prism needs at least 3 points, found 2");
  CHECK(povFailure("prism { quadratic_spline 0, 1, 5, <1, -1>, <0, 0>, <1, 0>, <1, 1>, <0, 1> }") ==
        "scene.pov:2:32: error: the prism's quadratic_spline loop starting at point 1 does not close");
  CHECK(povFailure("prism { bezier_spline 0, 1, 6, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 0>, <1, 1> }") ==
        "scene.pov:2:29: error: a bezier_spline prism needs a multiple of 4 points, found 6");
  CHECK(povFailure("prism { 0, 1, 4, <0, 0>, <1, 0>, <1, 1> }") == "scene.pov:2:1: error: 'prism' needs a prism point");
  CHECK(povFailure("prism { 0, 1, 2.5, <0, 0>, <1, 0>, <1, 1> }") ==
        "scene.pov:2:15: error: the number of prism points must be a whole number, found 2.5");
}

TEST_CASE("prism and lathe: the course language, which has no keywords in a shape, refuses them at their place",
          "[prism]") {
  for (const std::string shape : {"prism", "lathe"}) {
    std::string message = "no error";
    try {
      parsePov(shape + " { linear_spline 0, 1, 3, <0, 0>, <1, 0>, <0, 1> }\n", "course.pov");
    } catch (const Error& e) {
      message = e.what();
    }
    CHECK(message == "course.pov:1:" + std::to_string(shape.size() + 4) + ": error: '" + shape +
                         "' is read only in POV-Ray 3.7 scenes");
  }
}
