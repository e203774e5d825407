// T7 of docs/reference/stability.md §2: rays (nearly) parallel to a plane never produce a hit with a non-finite t or
// point.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "raytrace/shapes/plane.hpp"
#include "stability_support.hpp"

namespace rt {

// n·d ∈ {0, ±1e-30, ±1e-12, ±1e-7} with the origin above, on or below the plane, for axis-aligned and
// random planes: a hit, if any, has a finite t inside the interval, a finite point and a unit normal.
TEMPLATE_TEST_CASE("rays parallel to a plane give no hit or a finite one", "[stability][plane]", float, double) {
  using T = TestType;
  const double slope = GENERATE(0.0, 1e-30, -1e-30, 1e-12, -1e-12, 1e-7, -1e-7);
  const double height = GENERATE(1.0, 0.0, -1.0, 1e4, -1e4);
  const uint64_t seed = 0x5EED0200;
  CAPTURE(slope, height, seed);
  std::mt19937_64 rng(seed);
  for (int i = 0; i < 200; ++i) {
    const glm::dvec3 n = i == 0 ? glm::dvec3(0, 1, 0) : test::randomUnit(rng);
    const glm::dvec3 p0 = 10.0 * test::randomUnit(rng);  // a point of the plane
    glm::dvec3 e1, e2;
    test::frame(n, e1, e2);
    const Plane<T> plane(Vec3<T>(n), T(glm::dot(n, p0)), Material{}, 1);
    const Ray<T> ray{Vec3<T>(p0 + height * n), Vec3<T>(glm::normalize(e1 + slope * n))};
    const auto hit = plane.intersect(ray, Interval<T>{});
    if (!hit) continue;
    CAPTURE(i, hit->t);
    CHECK(std::isfinite(hit->t));
    CHECK(hit->t > T(0));
    CHECK(test::finite(hit->point));
    CHECK(std::abs(glm::length(glm::dvec3(hit->normal)) - 1) < 1e-6);
  }
}

}  // namespace rt
