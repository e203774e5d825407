// The surface of revolution: a constant radius is a cylinder with caps (or without, open); a vase keeps inside() and
// the crossings of random rays in step.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <string>

#include "crossing_parity.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/shapes/shape_desc.hpp"
#include "raytrace/shapes/sor.hpp"

using namespace rt;

namespace {

const Material kMaterial{};

std::unique_ptr<Object<double>> sor(const std::vector<glm::dvec2>& points, bool open = false, bool sturm = false) {
  return SorDesc{points, open, sturm}.make<double>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
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

const std::vector<glm::dvec2> kColumn{{1, -1}, {1, 0}, {1, 1}, {1, 2}};

}  // namespace

TEST_CASE("sor: a constant radius is a cylinder from the second point's height to the last but one's", "[sor]") {
  for (const bool sturm : {false, true}) {
    const auto column = sor(kColumn, false, sturm);
    const auto side = shoot(*column, {-5, 0.5, 0}, {1, 0, 0});
    REQUIRE(side);
    CHECK(side->t == Approx(4));
    CHECK(side->normal.x == Approx(-1));
    const auto slant = shoot(*column, {-5, 0, 0.6}, {1, 0.1, 0});
    REQUIRE(slant);
    CHECK(slant->point.x == Approx(-0.8));
    const auto top = shoot(*column, {0.2, 5, 0.3}, {0, -1, 0});
    REQUIRE(top);
    CHECK(top->t == Approx(4));
    CHECK(top->normal.y == Approx(1));
    const auto bottom = shoot(*column, {0.2, 0.5, 0.3}, {0, -1, 0});
    REQUIRE(bottom);
    CHECK(bottom->t == Approx(0.5));
    CHECK(bottom->normal.y == Approx(-1));
    CHECK(column->inside(Vec3<double>(0.5, 0.5, 0.5)));
    CHECK_FALSE(column->inside(Vec3<double>(0.5, 1.5, 0.5)));
    const auto bounds = *column->bounds();
    CHECK(bounds.min == glm::dvec3(-1, 0, -1));
    CHECK(bounds.max == glm::dvec3(1, 1, 1));
  }
  const auto open = sor(kColumn, true);
  CHECK_FALSE(shoot(*open, {0.2, 5, 0.3}, {0, -1, 0}));
  const auto wall = shoot(*open, {0, 0.5, 0}, {0, 0, 1});
  REQUIRE(wall);
  CHECK(wall->normal.z == Approx(1));
}

TEST_CASE("sor: random rays cross the manual's vase as inside() says", "[sor]") {
  const std::vector<glm::dvec2> vase{{0.000000, 0.000000}, {0.118143, 0.000000}, {0.620253, 0.540084},
                                     {0.210970, 0.827004}, {0.194093, 0.962025}, {0.286920, 1.000000},
                                     {0.468354, 1.033755}};
  CHECK(test::parityMismatches(*sor(vase), {-0.7, 0, -0.7}, {0.7, 1, 0.7}, 31) == 0);
  CHECK(test::parityMismatches(*sor(vase, false, true), {-0.7, 0, -0.7}, {0.7, 1, 0.7}, 32) == 0);
}

TEST_CASE("sor: bad input stops at the number of points, with what is wrong", "[sor]") {
  CHECK(povFailure("sor { 3, <1, 0>, <1, 1>, <1, 2> }") ==
        "scene.pov:2:7: error: a sor needs at least 4 points, found 3");
  CHECK(povFailure("sor { 4, <1, 0>, <1, 1>, <1, 1>, <1, 2> }") ==
        "scene.pov:2:7: error: the sor's heights must increase, but point 3's (1) is not above point 2's (1)");
}

TEST_CASE("sor, lathe and prism: open and sturm are read where POV-Ray has them", "[sor]") {
  const SceneDesc scene = povray::parsePovRay(
      "#version 3.7;\n"
      "sor { 4, <1, 0> <1, 1> <1, 2> <1, 3> open sturm pigment { rgb 1 } }\n"
      "lathe { bezier_spline 4, <1, 0>, <2, 0>, <2, 1>, <1, 1> sturm }\n"
      "prism { conic_sweep cubic_spline 0.5, 1, 6, <0, 1>, <1, 0>, <0, -1>, <-1, 0>, <1, 0>, <0, -1> open }\n",
      "scene.pov", povray::PovRayOptions{{}, 320, 240, false});
  REQUIRE(scene.objects.size() == 3);
  const auto& sor = std::get<SorDesc>(scene.objects[0].shape);
  CHECK(sor.open);
  CHECK(sor.sturm);
  const auto& lathe = std::get<LatheDesc>(scene.objects[1].shape);
  CHECK(lathe.spline == SplineKind::Bezier);
  CHECK(lathe.sturm);
  const auto& prism = std::get<PrismDesc>(scene.objects[2].shape);
  CHECK(prism.conic);
  CHECK(prism.spline == SplineKind::Cubic);
  CHECK(prism.open);
  CHECK(prism.outline.size() == 3);
}
