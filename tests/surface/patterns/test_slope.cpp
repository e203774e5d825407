// slope against POV-Ray 3.7's pictures: an orthographic view of a sphere at the origin, pigment
// `slope { … } color_map { [0 rgb 0] [1 rgb 1] }`, finish { ambient 1 diffuse 0 }, assumed_gamma 1, written as
// a 16-bit PPM; each row is a pixel's hit point on the sphere, whose normal is the point over the radius, and
// its grey.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "pov_scene.hpp"
#include "raytrace/surface/pattern.hpp"
#include "raytrace/surface/texture.hpp"

namespace rt {
namespace {

struct Sample {
  glm::dvec3 point;
  double grey;
};

// The pattern's value at each sample on a sphere of radius r, wrapped as the colour map wraps it.
void check(const SlopeArgs& args, double r, const std::vector<Sample>& samples) {
  PatternArgs a;
  a.slope = args;
  const auto pattern = makePattern(*patternKind("slope"), a);
  REQUIRE(pattern->readsNormal());
  for (const Sample& s : samples) {
    INFO("at " << s.point.x << ", " << s.point.y << ", " << s.point.z);
    setSurfaceNormal(s.point / r);
    double v = std::fmod(pattern->value(s.point), 1.00001);
    if (v < 0) v -= std::floor(v);
    CHECK(v == Approx(s.grey).margin(2e-5));  // POV-Ray's 16-bit grey
  }
}

TEST_CASE("slope: the angle to the direction, its range and the altitude, as POV-Ray draws them", "[patterns][slope]") {
  SECTION("slope { y }") {
    check({}, 1,
          {{{0, 0, -1}, 0.50001},
           {{-0.545455, 0.363636, -0.755148}, 0.61846},
           {{0.545455, 0.545455, -0.636364}, 0.68365},
           {{-0.363636, -0.545455, -0.755148}, 0.31635},
           {{0.363636, -0.363636, -0.857635}, 0.38154},
           {{0, -0.727273, -0.686349}, 0.24079}});
  }
  SECTION("slope { y*2, 0.25, 0.75 }: the range stretched, and wrapped past 1") {
    check({{0, 2, 0}, 0.25, 0.75}, 1,
          {{{-0.545455, 0.363636, -0.755148}, 0.73693},
           {{0.545455, 0.545455, -0.636364}, 0.86729},
           {{-0.363636, -0.545455, -0.755148}, 0.13271},
           {{0.363636, -0.363636, -0.857635}, 0.26307},
           {{0, -0.727273, -0.686349}, 0.98158}});
  }
  SECTION("slope { -y*3, 0, 0.5 altitude y, 0.005, 0.4 } (slopemt_36.pov's)") {
    check({{0, -3, 0}, 0, 0.5, {0, 1, 0}, 0.005, 0.4}, 1,
          {{{0, 0, -1}, 0.74684},
           {{-0.545455, 0.363636, -0.755148}, 0.79928},
           {{0.545455, 0.545455, -0.636364}, 0.81660},
           {{-0.363636, -0.545455, -0.755148}, 0.67707},
           {{0.363636, -0.363636, -0.857635}, 0.69438},
           {{0, -0.727273, -0.686349}, 0.67535}});
  }
  SECTION("slope { <0.8, -0.8, 0.4> altitude <0, 1, 1>, -2, 2 }: each part weighted by its vector's length") {
    check({{0.8, -0.8, 0.4}, 0, 1, {0, 1, 1}, -2, 2}, 3,
          {{{0, 0, -3}, 0.16345},
           {{-1.636364, 1.090909, -2.265443}, 0.23705},
           {{1.636364, 1.636364, -1.909091}, 0.44269},
           {{-1.090909, -1.636364, -2.265443}, 0.10774},
           {{1.090909, -1.090909, -2.572904}, 0.17890},
           {{-2.181818, 0, -2.059046}, 0.18698},
           {{0, -2.181818, -2.059046}, 0.13228}});
  }
}

TEST_CASE("slope: the scene reader's syntax, and the textures that read the normal", "[patterns][slope]") {
  const SceneDesc s = test::pov(R"(
plane { y, 0 pigment { slope { -y*3, 0, 0.5 altitude y, 0.005, 0.4 } } }
plane { y, 0 texture { slope { -z*0.8 altitude z } texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }
plane { y, 0 pigment { pigment_pattern { slope { y } } } }
plane { y, 0 pigment { gradient y } }
)");
  REQUIRE(s.objects.size() == 4);
  CHECK(s.objects[0].texture->readsNormal);
  CHECK(s.objects[1].texture->readsNormal);
  CHECK(s.objects[2].texture->readsNormal);
  CHECK_FALSE(s.objects[3].texture->readsNormal);
  // Facing straight up, away from −y, at height 0.2: (3·0 + (0.2 − 0.005)/0.395) / 4.
  setSurfaceNormal({0, 1, 0});
  CHECK(s.objects[0].texture->at({0, 0.2, 0}).pigment.r == Approx(0.195 / 0.395 / 4).margin(1e-6));
  // landscape.pov's, facing along x: (0.8·0.5 + 1·0.3) / 1.8.
  setSurfaceNormal({1, 0, 0});
  CHECK(s.objects[1].texture->at({0, 0, 0.3}).pigment.r == Approx(0.7 / 1.8).margin(1e-6));
}

TEST_CASE("slope: bad slopes stop the scene, point_at and functions are refused", "[patterns][slope]") {
  CHECK(test::povFailure("plane { y, 0 pigment { slope { 0 } } }") ==
        "scene.pov:2:24: error: slope needs a direction other than <0, 0, 0>");
  CHECK(test::povFailure("plane { y, 0 pigment { slope { y, 0.5, 0.5 } } }") ==
        "scene.pov:2:35: error: slope's slope range is empty");
  CHECK(test::povFailure("plane { y, 0 pigment { slope { y altitude y, 1 } } }") ==
        "scene.pov:2:46: error: slope's altitude range needs two floats");
  CHECK(test::povFailure("plane { y, 0 pigment { slope { y, 0, 1 bozo } } }") ==
        "scene.pov:2:40: error: slope takes a direction, a range and an altitude only");
  CHECK(test::povFailure("plane { y, 0 pigment { slope { point_at <0, 10, 0> } } }") ==
        "scene.pov:2:32: error: 'slope point_at' is not supported yet");
  CHECK(test::povFailure("sphere { 0, 1 pigment { function { pattern { slope { y } } } } }") ==
        "scene.pov:2:36: error: 'slope in a function' is not supported yet");
}

}  // namespace
}  // namespace rt
