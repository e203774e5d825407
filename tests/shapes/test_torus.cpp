#include <cmath>
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/shapes/torus.hpp"
#include "parse_message.hpp"
#include "shape_oracle.hpp"

using namespace rt;

namespace {

const Material kMaterial{};

template <class T> std::unique_ptr<Object<T>> torus(double major, double minor, bool sturm = false) {
  return TorusDesc{major, minor, sturm}.make<T>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
}

template <class T> std::optional<Hit<T>> shoot(const Object<T>& o, const Vec3<T>& origin, const Vec3<T>& dir) {
  return o.intersect(Ray<T>{origin, dir}, Interval<T>{});
}

// How deep a point is inside the tube: its radius less the distance to the centre circle.
template <class T> T depth(const Vec3<T>& p, T major, T minor) {
  const T rho = std::sqrt(p.x * p.x + p.z * p.z);
  return minor - std::sqrt((rho - major) * (rho - major) + p.y * p.y);
}

}  // namespace

TEMPLATE_TEST_CASE("a ray along the x axis meets the tube's outer and inner walls", "[torus]", float, double) {
  using T = TestType;
  for (const bool sturm : {false, true}) {
    const auto t = torus<T>(2, 0.5, sturm);
    const auto hit = shoot(*t, Vec3<T>(-5, 0, 0), Vec3<T>(1, 0, 0));
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.5).epsilon(1e-6));
    CHECK(hit->point.x == Approx(-2.5).epsilon(1e-6));
    CHECK(hit->normal.x == Approx(-1).epsilon(1e-6));
    // From inside the tube the exit is the inner wall, its normal towards the hole.
    const auto exit = shoot(*t, Vec3<T>(-2, 0, 0), Vec3<T>(1, 0, 0));
    REQUIRE(exit);
    CHECK(exit->t == Approx(0.5).epsilon(1e-6));
    CHECK(exit->normal.x == Approx(1).epsilon(1e-6));
    // Then the far side of the ring, across the hole.
    const auto across = t->intersect(Ray<T>{Vec3<T>(-5, 0, 0), Vec3<T>(1, 0, 0)}, Interval<T>{T(3.5), T(100)});
    REQUIRE(across);
    CHECK(across->t == Approx(6.5).epsilon(1e-6));
    CHECK(across->normal.x == Approx(-1).epsilon(1e-6));
  }
}

TEMPLATE_TEST_CASE("a ray down the y axis passes through the hole; one down the tube's centre meets its top", "[torus]",
                   float, double) {
  using T = TestType;
  const auto t = torus<T>(2, 0.5);
  CHECK_FALSE(shoot(*t, Vec3<T>(0, 5, 0), Vec3<T>(0, -1, 0)));
  const auto top = shoot(*t, Vec3<T>(0, 5, 2), Vec3<T>(0, -1, 0));
  REQUIRE(top);
  CHECK(top->t == Approx(4.5).epsilon(1e-6));
  CHECK(top->normal.y == Approx(1).epsilon(1e-6));
  // Diagonally onto the tube at 45° around the axis: the normal points away from the centre circle.
  const Vec3<T> ring(std::sqrt(T(2)), 0, std::sqrt(T(2)));
  const Vec3<T> out = glm::normalize(Vec3<T>(1, std::sqrt(T(2)), 1));  // 45° up from the radial direction
  const auto slanted = shoot(*t, ring + T(10) * out, -out);
  REQUIRE(slanted);
  CHECK(slanted->t == Approx(9.5).epsilon(1e-6));
  CHECK(glm::length(slanted->normal - out) < T(1e-5));
}

TEST_CASE("a torus far from the eye is hit to double precision", "[torus]") {
  const auto t = torus<double>(2, 0.5);
  for (const double far : {1e2, 1e4, 1e6}) {
    const auto hit = shoot(*t, glm::dvec3(0, 0.3, -far), glm::dvec3(0, 0, 1));
    REQUIRE(hit);
    CHECK(hit->t == Approx(far - 2 - std::sqrt(0.25 - 0.09)).epsilon(1e-12));
  }
}

TEMPLATE_TEST_CASE("the torus's box is exact and its inside is the tube", "[torus]", float, double) {
  using T = TestType;
  const auto t = torus<T>(2, 0.5);
  const auto box = t->bounds();
  REQUIRE(box);
  CHECK(box->min == Vec3<T>(T(-2.5), T(-0.5), T(-2.5)));
  CHECK(box->max == Vec3<T>(T(2.5), T(0.5), T(2.5)));
  CHECK(t->inside(Vec3<T>(2, 0, 0)));
  CHECK(t->inside(Vec3<T>(0, T(0.49), -2)));
  CHECK_FALSE(t->inside(Vec3<T>(0, T(0.51), -2)));
  CHECK_FALSE(t->inside(Vec3<T>(0, 0, 0)));
  CHECK_FALSE(t->inside(Vec3<T>(3, 0, 0)));
}

TEST_CASE("torus sweeps: hits against the tube's depth, crossings against inside()", "[torus]") {
  for (const bool sturm : {false, true}) {
    CAPTURE(sturm);
    const auto t = torus<double>(2, 0.5, sturm);
    test::sweep<double>(*t, [](const glm::dvec3& p) { return depth(p, 2.0, 0.5); }, glm::dvec3(-2.5, -0.5, -2.5),
                        glm::dvec3(2.5, 0.5, 2.5), 7);
    test::paritySweep<double>(*t, glm::dvec3(-2.5, -0.5, -2.5), glm::dvec3(2.5, 0.5, 2.5), 1e-6, 8);
    const auto thin = torus<double>(1, 0.05, sturm);
    test::paritySweep<double>(*thin, glm::dvec3(-1.05, -0.05, -1.05), glm::dvec3(1.05, 0.05, 1.05), 1e-7, 9);
  }
}

TEST_CASE("a spindle torus (major < minor) has its inside where the quartic is negative", "[torus]") {
  const auto t = torus<double>(0.5, 1);
  CHECK(t->inside(glm::dvec3(1, 0, 0)));
  CHECK_FALSE(t->inside(glm::dvec3(0, 0, 0)));  // in the lemon the two sides of the tube close off
  test::paritySweep<double>(*t, glm::dvec3(-1.5, -1, -1.5), glm::dvec3(1.5, 1, 1.5), 1e-6, 10);
}

using rt::test::messageOf;

TEST_CASE("a torus without a tube is refused where its minor radius is written", "[torus]") {
  CHECK(messageOf("torus { 1, 0 }") == "s.pov:2:12: error: the torus minor radius must be greater than 0, found 0");
  CHECK(messageOf("torus { -1, 0.5 }") == "s.pov:2:9: error: the torus major radius must not be negative, found -1");
}
