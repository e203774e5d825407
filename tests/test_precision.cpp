// The precision budget R = largest coordinate ÷ smallest feature and the arithmetic chosen from it
// (stability.md §1.1), on small scenes built here.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "raytrace/precision.hpp"

using rt::Arithmetic;
using rt::Precision;
using rt::SphereMethod;

namespace {

rt::SceneDesc withCamera(glm::dvec3 location) {
  rt::SceneDesc s;
  s.camera.location = location;
  return s;
}

void add(rt::SceneDesc& s, rt::ShapeDesc shape, glm::dmat4 m = glm::dmat4(1.0)) {
  rt::ObjectDesc o;
  o.shape = shape;
  o.worldFromObject = m;
  s.objects.push_back(o);
}

}  // namespace

TEST_CASE("precision: budget of a simple.pov-like scene") {
  rt::SceneDesc s = withCamera({0, 0, 14});
  add(s, rt::SphereDesc{{0, 0, 0}, 2});
  add(s, rt::PlaneDesc{{0, 1, 0}, -4});
  CHECK(rt::precisionBudget(s) == 7.0);  // camera at 14 over radius 2; the plane has no feature size
  const Arithmetic a = rt::chooseArithmetic(s);
  CHECK(a.precision == Precision::Float);
  CHECK(a.sphere == SphereMethod::Textbook);
}

TEST_CASE("precision: scenes of planes only, or nothing, have no feature to lose") {
  rt::SceneDesc s = withCamera({0, 0, 0.5});
  CHECK(rt::precisionBudget(s) == 1.0);
  add(s, rt::PlaneDesc{{0, 1, 0}, -40});
  CHECK(rt::precisionBudget(s) == 40.0);
}

TEST_CASE("precision: every shape's extent and smallest feature") {
  rt::SceneDesc s = withCamera({0, 0, 0});
  add(s, rt::TriangleDesc{{0, 0, 0}, {4, 0, 0}, {0, 3, 0}});  // sides 4, 5, 3; reaches 4
  CHECK(rt::precisionBudget(s) == Approx(4.0 / 3.0));
  add(s, rt::BoxDesc{{-1, -1, -1}, {9, 1, 1}});  // thinnest 2, reaches 9
  CHECK(rt::precisionBudget(s) == Approx(4.5));
  add(s, rt::CylinderDesc{{0, 0, 0}, {0, 0, 10}, 0.5});  // radius 0.5, reaches 10.5
  CHECK(rt::precisionBudget(s) == Approx(21.0));
  add(s, rt::ConeDesc{{0, 0, 0}, 0.25, {0, 1, 0}, 0});  // larger radius 0.25
  CHECK(rt::precisionBudget(s) == Approx(42.0));
}

TEST_CASE("precision: transforms scale both the extent and the features") {
  rt::SceneDesc s = withCamera({0, 0, 1});
  add(s, rt::SphereDesc{{0, 0, 0}, 1}, glm::scale(glm::dmat4(1.0), glm::dvec3(0.1, 1, 1)));
  CHECK(rt::precisionBudget(s) == Approx(10.0));  // thinnest axis 0.1, extent 1
  rt::SceneDesc t = withCamera({0, 0, 1});
  add(t, rt::SphereDesc{{0, 0, 0}, 1}, glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 99)));
  CHECK(rt::precisionBudget(t) == Approx(100.0));
}

TEST_CASE("precision: the thresholds R = 50 and R = 1000") {
  const auto choose = [](double cameraZ) {
    rt::SceneDesc s = withCamera({0, 0, cameraZ});
    add(s, rt::SphereDesc{{0, 0, 0}, 1});
    return rt::chooseArithmetic(s);
  };
  CHECK(choose(50).precision == Precision::Float);
  CHECK(choose(50).sphere == SphereMethod::Textbook);
  CHECK(choose(50.5).precision == Precision::Float);
  CHECK(choose(50.5).sphere == SphereMethod::Robust);
  CHECK(choose(1000).precision == Precision::Float);
  CHECK(choose(1000).sphere == SphereMethod::Robust);
  CHECK(choose(1000.5).precision == Precision::Double);
  CHECK(choose(1000.5).sphere == SphereMethod::Robust);
}

TEST_CASE("precision: explicit requests win") {
  rt::SceneDesc s = withCamera({0, 0, 1e4});
  add(s, rt::SphereDesc{{0, 0, 0}, 1});
  const Arithmetic forced = rt::chooseArithmetic(s, {Precision::Float, SphereMethod::Textbook});
  CHECK(forced.precision == Precision::Float);
  CHECK(forced.sphere == SphereMethod::Textbook);
  rt::SceneDesc small = withCamera({0, 0, 5});
  add(small, rt::SphereDesc{{0, 0, 0}, 1});
  const Arithmetic dbl = rt::chooseArithmetic(small, {Precision::Double, SphereMethod::Auto});
  CHECK(dbl.precision == Precision::Double);
  CHECK(dbl.sphere == SphereMethod::Robust);  // the textbook formula is only ever chosen for float
  CHECK(rt::chooseArithmetic(small, {Precision::Auto, SphereMethod::Robust}).sphere == SphereMethod::Robust);
}

TEST_CASE("precision: withPrecision calls the lambda with the chosen type") {
  CHECK(rt::withPrecision(Precision::Float, [](auto t) { return sizeof(t); }) == sizeof(float));
  CHECK(rt::withPrecision(Precision::Double, [](auto t) { return sizeof(t); }) == sizeof(double));
}
