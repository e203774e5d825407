// POV-Ray's splines called as S(t) and in `function { spline { … } }`, and `function { transform { … } }`
// (transforms.inc's vtransform and vinv_transform), against the values real POV-Ray 3.7 printed with #debug.
#include <catch2/catch.hpp>

#include <string>

#include "../../support/pov_scene.hpp"
#include "raytrace/shapes/sphere.hpp"

namespace {

using rt::test::pov;
using rt::test::povFailure;

// Five points at uneven parameter values.
const std::string kPoints = "0, <0,0,0> 1, <1,2,0> 3, <2,-1,1> 4, <4,0,2> 6, <5,3,0>";

// The centre of the scene's only object, a sphere at `where`.
glm::dvec3 at(const std::string& declarations, const std::string& where) {
  const rt::SceneDesc s = pov(declarations + "\nsphere { " + where + ", 1 }");
  return std::get<rt::SphereDesc>(s.objects.at(0).shape).center;
}

void check(glm::dvec3 got, glm::dvec3 expected) {
  for (int i = 0; i < 3; ++i) CHECK(got[i] == Approx(expected[i]).margin(1e-9));
}

}  // namespace

TEST_CASE("spline: each kind between and beyond its points, as POV-Ray prints it", "[povray]") {
  struct Case {
    const char* kind;
    double t;
    glm::dvec3 value;
  } cases[] = {
      {"linear_spline", -1, {0, 0, 0}},
      {"linear_spline", 1.5, {1.25, 1.25, 0.25}},
      {"linear_spline", 4.5, {4.25, 0.75, 1.5}},
      {"linear_spline", 7, {5, 3, 0}},
      {"quadratic_spline", 0.5, {0.541666667, 1.291666667, -0.041666667}},
      {"quadratic_spline", 2.5, {1.875, 0.625, 0.625}},
      {"quadratic_spline", 3.5, {2.875, -0.708333333, 1.458333333}},
      {"quadratic_spline", 5, {5, 1.333333333, 1.666666667}},
      {"cubic_spline", 0.5, {1, 2, 0}},
      {"cubic_spline", 1.5, {1.25, 1.625, 0.15625}},
      {"cubic_spline", 2.5, {1.5625, -0.4375, 0.65625}},
      {"cubic_spline", 3.5, {3, -0.6875, 1.59375}},
      {"cubic_spline", 5, {4, 0, 2}},
      {"natural_spline", 0.5, {0.577620968, 1.305443548, -0.015120968}},
      {"natural_spline", 2, {1.254032258, 0.681451613, 0.245967742}},
      {"natural_spline", 3.5, {2.977822581, -0.747983871, 1.584677419}},
      {"natural_spline", 5.5, {5.042338710, 2.280241935, 0.832661290}},
      {"natural_spline", 6.5, {5, 3, 0}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.kind, c.t);
    check(at("#declare S = spline { " + std::string(c.kind) + " " + kPoints + " }", "S(" + std::to_string(c.t) + ")"),
          c.value);
  }
  // Evaluated as another kind; a spline's own points in another order; a cubic spline of three points stays
  // at its second.
  check(at("#declare S = spline { natural_spline " + kPoints + " }", "S(2.5, linear_spline)"), {1.75, -0.25, 0.75});
  check(at("#declare S = spline { 3, <2,-1,1> 0, <0,0,0> 1, <1,2,0> }", "S(2)"), {1.5, 0.5, 0.5});
  check(at("#declare S = spline { cubic_spline 0, <0,0,0> 1, <1,2,0> 3, <2,-1,1> }", "S(2)"), {1, 2, 0});
}

TEST_CASE("spline: a spline function gives its spline's value; inside another function it is refused", "[povray]") {
  const std::string f = "#declare F = function { spline { cubic_spline " + kPoints + " } }";
  check(at(f, "F(2.5)"), {1.5625, -0.4375, 0.65625});
  CHECK(povFailure(f + "\n#declare G = function { F(x).y }\nsphere { 0, 1 pigment { function { G(x, y, z) } } }") ==
        "scene.pov:4:36: error: 'G' is not supported yet");
  CHECK(povFailure("#declare S = spline { 0, <0,0,0> 1, <1,1,1> }\nsphere { S(0.5, wavy_spline), 1 }") ==
        "scene.pov:3:17: error: expected a spline type, found 'wavy_spline'");
}

TEST_CASE("transform function: the point moved by the transform, or by its inverse", "[povray]") {
  const std::string t = "#declare T = transform { rotate <10,20,30> scale <1,2,3> translate <1,-1,2> }\n"
                        "#declare F = function { transform { T } }\n"
                        "#declare G = function { transform { T inverse } }";
  // POV-Ray's vtransform(<1,2,3>, T) and vinv_transform(<1,2,3>, T).
  check(at(t, "F(1, 2, 3)"), {2.067425379, 3.578118965, 10.281744243});
  check(at(t, "G(1, 2, 3)"), {0.590762751, 1.378238149, 0.335514660});
  check(at(t, "<F(1, 2, 3).x, 0, 0>"), {2.067425379, 0, 0});
}
