#include <cmath>
#include <random>

#include <catch2/catch.hpp>

#include "raytrace/shapes/triangle.hpp"

using namespace rt;
using Catch::Matchers::WithinAbs;

namespace {

const Material kMaterial;

template <class T> Triangle<T> unitTriangle() {
  return Triangle<T>(Vec3<T>(0, 0, 0), Vec3<T>(1, 0, 0), Vec3<T>(0, 1, 0), kMaterial, 1);
}

template <class T> Ray<T> down(T x, T y) { return Ray<T>{Vec3<T>(x, y, 1), Vec3<T>(0, 0, -1)}; }

}  // namespace

TEMPLATE_TEST_CASE("A ray through a triangle hits it with the (b-a)x(c-a) normal", "[triangle]", float, double) {
  using T = TestType;
  const Triangle<T> tri = unitTriangle<T>();
  const auto hit = tri.intersect(down<T>(0.25, 0.25), {});
  REQUIRE(hit);
  CHECK(hit->t == T(1));
  CHECK(hit->point == Vec3<T>(0.25, 0.25, 0));
  CHECK(hit->normal == Vec3<T>(0, 0, 1));
  CHECK(hit->object == &tri);
  // From behind: hit too, and the normal stays the geometric one.
  const auto back = tri.intersect(Ray<T>{Vec3<T>(0.25, 0.25, -2), Vec3<T>(0, 0, 1)}, {});
  REQUIRE(back);
  CHECK(back->t == T(2));
  CHECK(back->normal == Vec3<T>(0, 0, 1));
}

TEMPLATE_TEST_CASE("Triangle edges and vertices count as inside; outside misses", "[triangle]", float, double) {
  using T = TestType;
  const Triangle<T> tri = unitTriangle<T>();
  CHECK(tri.intersect(down<T>(0.5, 0.5), {}));   // on the hypotenuse
  CHECK(tri.intersect(down<T>(0.5, 0), {}));     // on an edge
  CHECK(tri.intersect(down<T>(0, 0), {}));       // a vertex
  CHECK_FALSE(tri.intersect(down<T>(0.6, 0.6), {}));
  CHECK_FALSE(tri.intersect(down<T>(-0.01, 0.5), {}));
  CHECK_FALSE(tri.intersect(down<T>(0.5, -0.01), {}));
}

TEMPLATE_TEST_CASE("A triangle respects the open interval and ignores parallel rays", "[triangle]", float, double) {
  using T = TestType;
  const Triangle<T> tri = unitTriangle<T>();
  CHECK_FALSE(tri.intersect(down<T>(0.25, 0.25), {T(0), T(1)}));  // t = 1 is not inside (0, 1)
  CHECK(tri.intersect(down<T>(0.25, 0.25), {T(0), T(1.001)}));
  CHECK_FALSE(tri.intersect(Ray<T>{Vec3<T>(0.25, 0.25, -1), Vec3<T>(0, 0, -1)}, {}));  // behind the origin
  // In the plane, and parallel above it.
  CHECK_FALSE(tri.intersect(Ray<T>{Vec3<T>(-1, 0.25, 0), Vec3<T>(1, 0, 0)}, {}));
  CHECK_FALSE(tri.intersect(Ray<T>{Vec3<T>(-1, 0.25, 1), Vec3<T>(1, 0, 0)}, {}));
}

TEMPLATE_TEST_CASE("Degenerate triangles are never hit and never produce NaN", "[triangle]", float, double) {
  using T = TestType;
  const Triangle<T> line(Vec3<T>(0, 0, 0), Vec3<T>(1, 1, 0), Vec3<T>(2, 2, 0), kMaterial, 1);
  const Triangle<T> point(Vec3<T>(1, 1, 0), Vec3<T>(1, 1, 0), Vec3<T>(1, 1, 0), kMaterial, 2);
  const unsigned seed = 3451;
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<T> u(-3, 3);
  for (int i = 0; i < 2000; ++i) {
    const Ray<T> ray{Vec3<T>(u(rng), u(rng), u(rng)), glm::normalize(Vec3<T>(u(rng), u(rng), u(rng)))};
    CAPTURE(i);
    CHECK_FALSE(line.intersect(ray, {}));
    CHECK_FALSE(point.intersect(ray, {}));
  }
  CHECK_FALSE(line.intersect(Ray<T>{Vec3<T>(1, 1, 1), Vec3<T>(0, 0, -1)}, {}));  // straight at the segment
}

TEMPLATE_TEST_CASE("Random hits on a triangle lie on it, with finite t", "[triangle]", float, double) {
  using T = TestType;
  const Triangle<T> tri(Vec3<T>(-1, 0, -3), Vec3<T>(2, 0.5, -4), Vec3<T>(0, 2, -3.5), kMaterial, 1);
  const unsigned seed = 11;
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<T> u(0, 1);
  for (int i = 0; i < 2000; ++i) {
    T a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const Vec3<T> target = Vec3<T>(-1, 0, -3) + a * Vec3<T>(3, 0.5, -1) + b * Vec3<T>(1, 2, -0.5);
    const Vec3<T> origin(u(rng), u(rng), 2);
    CAPTURE(i, a, b);
    const auto hit = tri.intersect(Ray<T>{origin, glm::normalize(target - origin)}, {});
    REQUIRE(hit);
    CHECK(std::isfinite(hit->t));
    CHECK_THAT(double(glm::length(hit->point - target)), WithinAbs(0.0, 1e-5));
  }
}

TEST_CASE("A triangle's bounds are its vertices' box", "[triangle]") {
  const Triangle<double> tri(Vec3<double>(-1, 0, 3), Vec3<double>(2, 0.5, -4), Vec3<double>(0, 2, 1), kMaterial, 1);
  const auto box = tri.bounds();
  REQUIRE(box);
  CHECK(box->min == Vec3<double>(-1, 0, -4));
  CHECK(box->max == Vec3<double>(2, 2, 3));
}
