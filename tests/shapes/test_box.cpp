#include <catch2/catch.hpp>

#include "raytrace/shapes/box.hpp"
#include "shape_oracle.hpp"

using namespace rt;

namespace {

template <class T> Box<T> unitBox() { return Box<T>(Vec3<T>(-1), Vec3<T>(1), Material{}, 1); }

template <class T> T boxDepth(const Vec3<T>& p, const Vec3<T>& lo, const Vec3<T>& hi) {
  const Vec3<T> d = glm::min(p - lo, hi - p);
  return glm::min(d.x, glm::min(d.y, d.z));
}

}  // namespace

TEMPLATE_TEST_CASE("a ray from outside hits the face it enters, with that face's outward normal", "[box]", float,
                   double) {
  using T = TestType;
  const Box<T> box = unitBox<T>();
  for (int axis = 0; axis < 3; ++axis) {
    for (const T side : {T(-1), T(1)}) {
      CAPTURE(axis, side);
      Vec3<T> origin(T(0.25), T(-0.5), T(0.75));
      origin[axis] = T(5) * side;
      Vec3<T> dir(0);
      dir[axis] = -side;
      const auto hit = box.intersect(Ray<T>{origin, dir}, Interval<T>{});
      REQUIRE(hit);
      CHECK(hit->t == T(4));
      Vec3<T> normal(0), point = origin;
      normal[axis] = side;
      point[axis] = side;
      CHECK(hit->normal == normal);
      CHECK(hit->point == point);
      CHECK(hit->object == &box);
    }
  }
}

TEMPLATE_TEST_CASE("a ray from inside hits the exit face, whose outward normal points along the ray", "[box]",
                   float, double) {
  using T = TestType;
  const auto hit = unitBox<T>().intersect(Ray<T>{Vec3<T>(T(0.5), 0, 0), Vec3<T>(0, 0, -1)}, Interval<T>{});
  REQUIRE(hit);
  CHECK(hit->t == T(1));
  CHECK(hit->normal == Vec3<T>(0, 0, -1));
  CHECK(hit->point == Vec3<T>(T(0.5), 0, -1));
}

TEMPLATE_TEST_CASE("the corners may come in any order", "[box]", float, double) {
  using T = TestType;
  const Box<T> box(Vec3<T>(2, -1, 3), Vec3<T>(-2, 1, -3), Material{}, 1);
  const auto bounds = box.bounds();
  REQUIRE(bounds);
  CHECK(bounds->min == Vec3<T>(-2, -1, -3));
  CHECK(bounds->max == Vec3<T>(2, 1, 3));
  const auto hit = box.intersect(Ray<T>{Vec3<T>(0, 0, 10), Vec3<T>(0, 0, -1)}, Interval<T>{});
  REQUIRE(hit);
  CHECK(hit->t == T(7));
  CHECK(hit->normal == Vec3<T>(0, 0, 1));
}

TEMPLATE_TEST_CASE("rays lying in a face plane or along an edge graze the box without NaN", "[box]", float,
                   double) {
  using T = TestType;
  const Box<T> box = unitBox<T>();
  // In the plane y = 1 of the top face, and along the edge y = z = 1: the face x = −1 is entered at t = 4.
  for (const Vec3<T> origin : {Vec3<T>(-5, 1, 0), Vec3<T>(-5, 1, 1), Vec3<T>(-5, -1, -1)}) {
    CAPTURE(origin.x, origin.y, origin.z);
    const auto hit = box.intersect(Ray<T>{origin, Vec3<T>(1, 0, 0)}, Interval<T>{});
    REQUIRE(hit);
    CHECK(hit->t == T(4));
    CHECK(hit->normal == Vec3<T>(-1, 0, 0));
    CHECK(hit->point == Vec3<T>(-1, origin.y, origin.z));
  }
  // Just above the top face it misses.
  CHECK_FALSE(box.intersect(Ray<T>{Vec3<T>(-5, T(1.0001), 0), Vec3<T>(1, 0, 0)}, Interval<T>{}));
  // Starting on a face and running along it: only the far edge lies ahead.
  const auto along = box.intersect(Ray<T>{Vec3<T>(0, 1, 0), Vec3<T>(1, 0, 0)}, Interval<T>{});
  REQUIRE(along);
  CHECK(along->t == T(1));
  CHECK(along->normal == Vec3<T>(1, 0, 0));
}

TEMPLATE_TEST_CASE("rays through a corner or touching an edge hit it", "[box]", float, double) {
  using T = TestType;
  const auto hit = unitBox<T>().intersect(Ray<T>{Vec3<T>(-3, -3, -3), Vec3<T>(1, 1, 1)}, Interval<T>{});
  REQUIRE(hit);
  CHECK(hit->t == T(2));
  CHECK(hit->point == Vec3<T>(-1, -1, -1));
  CHECK(glm::length(hit->normal) == T(1));
  // Touching only the edge x = y = −1 (entry and exit at the same t): inclusive, so it is hit there.
  const auto edge = unitBox<T>().intersect(Ray<T>{Vec3<T>(-2, 0, 0), Vec3<T>(1, -1, 0)}, Interval<T>{});
  REQUIRE(edge);
  CHECK(edge->t == T(1));
  CHECK(edge->point == Vec3<T>(-1, -1, 0));
}

TEMPLATE_TEST_CASE("the box answers only inside the open interval", "[box]", float, double) {
  using T = TestType;
  const Box<T> box = unitBox<T>();
  const Ray<T> ray{Vec3<T>(0, 0, 5), Vec3<T>(0, 0, -1)};
  CHECK_FALSE(box.intersect(ray, Interval<T>{0, 4}));  // the entry at t = 4 is excluded
  const auto exit = box.intersect(ray, Interval<T>{4, 100});
  REQUIRE(exit);
  CHECK(exit->t == T(6));
  CHECK(exit->normal == Vec3<T>(0, 0, -1));
  CHECK_FALSE(box.intersect(ray, Interval<T>{6, 100}));
  CHECK_FALSE(box.intersect(Ray<T>{Vec3<T>(0, 0, 5), Vec3<T>(0, 0, 1)}, Interval<T>{}));  // behind
}

TEMPLATE_TEST_CASE("a non-unit direction keeps t in its units", "[box]", float, double) {
  using T = TestType;
  const auto hit = unitBox<T>().intersect(Ray<T>{Vec3<T>(0, 0, 5), Vec3<T>(0, 0, -2)}, Interval<T>{});
  REQUIRE(hit);
  CHECK(hit->t == T(2));
}

TEMPLATE_TEST_CASE("box sweep against the inside/outside oracle", "[box]", float, double) {
  using T = TestType;
  const Vec3<T> lo(T(-1.5), T(0.25), T(-3)), hi(T(2), T(1), T(-0.5));
  const Box<T> box(hi, lo, Material{}, 1);
  const auto seed = GENERATE(1u, 2u, 3u);
  test::sweep<T>(box, [&](const Vec3<T>& p) { return boxDepth(p, lo, hi); }, lo, hi, seed);
}
