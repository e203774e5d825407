// tiling N against the values POV-Ray 3.7 printed at these points: POV-Ray's pattern functions do not take
// tiling, so its value is read through `#declare F = function { pigment { tiling N color_map { [0 rgb 0]
// [1 rgb 1] } } }` as F(x, y, z).red, written with #debug str(…, 0, 6).
#include <catch2/catch.hpp>

#include <vector>

#include "pov_scene.hpp"
#include "raytrace/surface/pattern.hpp"

namespace rt {
namespace {

// Points at random, none on a tile's edge (where two tiles' values meet) nor on an integer x or z.
const glm::dvec3 kPoints[] = {{0.3, 0.7, 0.2},   {1.37, -2, 0.81}, {-0.62, 0.5, 1.93}, {2.71, 0, -1.18},
                              {-3.14, 1, -2.72}, {0.95, 3, 0.05},  {4.4, 0, 2.9},      {-1.73, 0, -0.41},
                              {0.51, 0, 1.55},   {2.2, -1, 3.3},   {-0.07, 0, -0.93},  {5.58, 2, -4.12}};

void check(int number, const std::vector<double>& expected) {
  PatternArgs a;
  a.vector = glm::dvec3(number);
  a.hasVector = true;
  const auto pattern = makePattern(*patternKind("tiling"), a);
  REQUIRE(expected.size() == std::size(kPoints));
  for (size_t i = 0; i < expected.size(); ++i) {
    INFO("tiling " << number << " at point " << i);
    CHECK(pattern->value(kPoints[i]) == Approx(expected[i]).margin(1e-6));
  }
}

TEST_CASE("tiling: the tiles' values and bevels as POV-Ray gives them", "[patterns][tiling]") {
  check(1, {0.6, 0.62, 0.86, 0.64, 0.72, 0.9, 0.8, 0.46, 0.1, 0.6, 0.86, 0.76});
  check(2, {0.769060, 0.902346, 0.494286, 0.971273, 0.710393, 0.942265, 0.925684, 0.966714, 0.789786, 0.294744,
            0.606936, 0.958683});
  check(3, {0.223205, 0.902961, 0.157142, 0.956910, 0.788822, 0.468301, 0.888526, 0.950070, 0.684679, 0.842116,
            0.889193, 0.938025});
  check(4, {0.630940, 0.870615, 0.542856, 0.274907, 0.718429, 0.884530, 0.451368, 0.053146, 0.579572, 0.621024,
            0.852257, 0.917366});
  check(6, {0.8, 0.31, 0.43, 0.71, 0.86, 0.95, 0.4, 0.73, 0.55, 0.8, 0.93, 0.38});
  // Octagons among squares: an octagon's middle, farther from its edges than a square's, stays at 0.5.
  check(7, {0.5, 0.395980, 0.573690, 0.972893, 0.522325, 0.742893, 0.5, 0.566619, 0.764609, 0.678680, 0.722893,
            0.825269});
  check(8, {0.769060, 0.780607, 0.926129, 0.757513, 0.319418, 0.942265, 0.294103, 0.633380, 0.160876, 0.283889,
            0.926129, 0.470649});
  check(9, {0.769060, 0.902346, 0.771428, 0.971273, 0.666667, 0.942265, 0.592351, 0.633380, 0.789786, 0.561411,
            0.666667, 0.666667});
  check(10, {0.6, 0.62, 0.86, 0.64, 0.44, 0.9, 0.8, 0.54, 0.98, 0.4, 0.86, 0.84});
  check(5, {0.210313, 0.290205, 0.847619, 0.647516, 0.473595, 0.294843, 0.617123, 0.644476, 0.859857, 0.207008,
            0.404624, 0.305789});
}

TEST_CASE("tiling: the square tiling's bevel is exact: 0 at a tile's centre, 1 on its edges", "[patterns][tiling]") {
  PatternArgs a;
  a.vector = glm::dvec3(1);
  const auto pattern = makePattern(*patternKind("tiling"), a);
  CHECK(pattern->value({0.5, 0, 0.5}) == Approx(0).margin(1e-12));
  CHECK(pattern->value({0.75, 0, 0.5}) == Approx(0.5));
  CHECK(pattern->value({-0.5, 7, 0.999}) == Approx(0.998));
}

TEST_CASE("tiling: the scene reader's number", "[patterns][tiling]") {
  CHECK(test::povFailure("plane { y, 0 pigment { tiling 5 } }") == "no error");
  CHECK(test::povFailure("plane { y, 0 pigment { tiling 28 } }") ==
        "scene.pov:2:24: error: tiling number must be between 1 and 27");
  CHECK(test::povFailure("plane { y, 0 pigment { tiling 0.5 } }") ==
        "scene.pov:2:24: error: tiling number must be between 1 and 27");
  CHECK(test::povFailure("plane { y, 0 pigment { tiling 27 } }") ==
        "scene.pov:2:24: error: 'tiling 27' is not supported yet");
  CHECK(test::povFailure("plane { y, 0 pigment { tiling } }") ==
        "scene.pov:2:24: error: 'tiling' needs a number or a vector");
}

}  // namespace
}  // namespace rt
