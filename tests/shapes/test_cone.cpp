#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "raytrace/shapes/cone.hpp"
#include "shape_oracle.hpp"

using namespace rt;

namespace {

template <class T> std::optional<Hit<T>> shoot(const Cone<T>& c, const Vec3<T>& origin, const Vec3<T>& dir) {
  return c.intersect(Ray<T>{origin, dir}, Interval<T>{});
}

template <class T> void checkNear(const Vec3<T>& a, const Vec3<T>& b) {
  CAPTURE(a.x, a.y, a.z, b.x, b.y, b.z);
  CHECK(glm::length(a - b) < T(1e-6));
}

// Radius 1 at y = 0 narrowing to a point at y = 2.
template <class T> Cone<T> pointed() { return Cone<T>(Vec3<T>(0), T(1), Vec3<T>(0, 2, 0), T(0), Material{}, 1); }

}  // namespace

TEMPLATE_TEST_CASE("the side of a cone, with the normal tilted by the slope", "[cone]", float, double) {
  using T = TestType;
  const Cone<T> c = pointed<T>();
  // At y = 1 the radius is 0.5; the outward normal is ∝ (1, −k, 0) with k = −1/2.
  const auto hit = shoot(c, Vec3<T>(5, 1, 0), Vec3<T>(-1, 0, 0));
  REQUIRE(hit);
  CHECK(hit->t == T(4.5));
  checkNear(hit->point, Vec3<T>(T(0.5), 1, 0));
  checkNear(hit->normal, glm::normalize(Vec3<T>(1, T(0.5), 0)));
  // From inside, at y = 0.5 (radius 0.75).
  const auto exit = shoot(c, Vec3<T>(0, T(0.5), 0), Vec3<T>(0, 0, -1));
  REQUIRE(exit);
  CHECK(exit->t == T(0.75));
  checkNear(exit->normal, glm::normalize(Vec3<T>(0, T(0.5), -1)));
}

TEMPLATE_TEST_CASE("a ray along the axis meets the base disk and the apex", "[cone]", float, double) {
  using T = TestType;
  const Cone<T> c = pointed<T>();
  const auto base = shoot(c, Vec3<T>(0, -5, 0), Vec3<T>(0, 1, 0));
  REQUIRE(base);
  CHECK(base->t == T(5));
  CHECK(base->normal == Vec3<T>(0, -1, 0));
  const auto apex = shoot(c, Vec3<T>(0, 5, 0), Vec3<T>(0, -1, 0));
  REQUIRE(apex);
  CHECK(apex->t == T(3));
  // Re-projected the rim margin, 8ε·(|base| + height + radius), below the apex (docs/reference/stability.md F6).
  CHECK(glm::length(apex->point - Vec3<T>(0, 2, 0)) <= 64 * std::numeric_limits<T>::epsilon());
  CHECK(apex->normal == Vec3<T>(0, 1, 0));
  // Parallel to the axis, off it: the side, where the radius is 0.5.
  const auto side = shoot(c, Vec3<T>(T(0.5), 5, 0), Vec3<T>(0, -1, 0));
  REQUIRE(side);
  CHECK(side->t == Approx(4).epsilon(1e-6));
  checkNear(side->normal, glm::normalize(Vec3<T>(1, T(0.5), 0)));
}

TEMPLATE_TEST_CASE("a truncated cone is closed by both disks", "[cone]", float, double) {
  using T = TestType;
  // Radius 2 at z = 0, radius 1 at z = 2.
  const Cone<T> c(Vec3<T>(0), T(2), Vec3<T>(0, 0, 2), T(1), Material{}, 1);
  const auto cap = shoot(c, Vec3<T>(T(0.5), 0, 5), Vec3<T>(0, 0, -1));
  REQUIRE(cap);
  CHECK(cap->t == T(3));
  CHECK(cap->normal == Vec3<T>(0, 0, 1));
  CHECK(cap->point == Vec3<T>(T(0.5), 0, 2));
  // Outside the cap disk, inside the base: the side where the radius is 1.5, at z = 1.
  const auto side = shoot(c, Vec3<T>(T(1.5), 0, 5), Vec3<T>(0, 0, -1));
  REQUIRE(side);
  CHECK(side->t == Approx(4).epsilon(1e-6));
  checkNear(side->normal, glm::normalize(Vec3<T>(1, 0, T(0.5))));
  const auto base = shoot(c, Vec3<T>(T(1.5), 0, -5), Vec3<T>(0, 0, 1));
  REQUIRE(base);
  CHECK(base->t == T(5));
  CHECK(base->normal == Vec3<T>(0, 0, -1));
  // The rim of the cap: inclusive bounds, no crack.
  const auto rim = shoot(c, Vec3<T>(1, 0, 5), Vec3<T>(0, 0, -1));
  REQUIRE(rim);
  CHECK(rim->t == T(3));
}

TEMPLATE_TEST_CASE("a zero radius is a point, with no disk", "[cone]", float, double) {
  using T = TestType;
  // Radius 0 at the base y = 0, radius 1 at y = 1.
  const Cone<T> c(Vec3<T>(0), T(0), Vec3<T>(0, 1, 0), T(1), Material{}, 1);
  const auto side = shoot(c, Vec3<T>(T(0.5), -5, 0), Vec3<T>(0, 1, 0));
  REQUIRE(side);
  CHECK(side->t == Approx(5.5).epsilon(1e-6));
  checkNear(side->normal, glm::normalize(Vec3<T>(1, -1, 0)));
  const auto apex = shoot(c, Vec3<T>(0, -5, 0), Vec3<T>(0, 1, 0));
  REQUIRE(apex);
  CHECK(apex->t == T(5));
  CHECK(apex->normal == Vec3<T>(0, -1, 0));
}

TEMPLATE_TEST_CASE("a ray parallel to a generator line has one side root", "[cone]", float, double) {
  using T = TestType;
  // Slope −1: the generator through (1, 0, 0) runs along (−1, 1, 0). From inside at (0, 0.1, 0) the ray
  // meets the side where |x| = 1 − y, at x = −0.45.
  const Cone<T> c(Vec3<T>(0), T(1), Vec3<T>(0, 1, 0), T(0), Material{}, 1);
  const Vec3<T> dir = glm::normalize(Vec3<T>(-1, 1, 0));
  const auto hit = shoot(c, Vec3<T>(0, T(0.1), 0), dir);
  REQUIRE(hit);
  CHECK(hit->t == Approx(0.45 * std::sqrt(2.0)).epsilon(1e-6));
  checkNear(hit->point, Vec3<T>(T(-0.45), T(0.55), 0));
  checkNear(hit->normal, glm::normalize(Vec3<T>(-1, 1, 0)));
}

TEMPLATE_TEST_CASE("rays nearly parallel or perpendicular to the cone axis give finite t", "[cone]", float,
                   double) {
  using T = TestType;
  const Cone<T> c(Vec3<T>(0), T(1), Vec3<T>(0, 2, 0), T(T(0.5)), Material{}, 1);
  const T delta = GENERATE(T(0), T(1e-20), T(1e-12), T(1e-7), T(1e-4));
  const T sign = GENERATE(T(-1), T(1));
  CAPTURE(delta, sign);
  const Vec3<T> dir = glm::normalize(Vec3<T>(delta, sign, 0));
  const auto hit = shoot(c, Vec3<T>(T(0.3), T(1) - sign * 5, 0), dir);
  REQUIRE(hit);
  REQUIRE(std::isfinite(hit->t));
  CHECK(hit->t == Approx(T(4) / std::abs(dir.y)).epsilon(1e-6));
  CHECK(hit->normal == Vec3<T>(0, -sign, 0));
  CHECK_FALSE(shoot(c, Vec3<T>(3, T(1) - sign * 5, 0), dir));
  // Across the axis at the heights of the ends, and beyond them.
  for (const T y : {T(-0.5), T(0), T(2), T(2.5)}) {
    CAPTURE(y);
    const auto across = shoot(c, Vec3<T>(0, y, 5), Vec3<T>(0, 0, -1));
    CHECK(bool(across) == (y >= 0 && y <= 2));
    if (across) REQUIRE(std::isfinite(across->t));
  }
}

TEMPLATE_TEST_CASE("cone bounds", "[cone]", float, double) {
  using T = TestType;
  const auto bounds = pointed<T>().bounds();
  REQUIRE(bounds);
  CHECK(bounds->min == Vec3<T>(-1, 0, -1));
  CHECK(bounds->max == Vec3<T>(1, 2, 1));
}

TEMPLATE_TEST_CASE("cone sweep against the inside/outside oracle", "[cone]", float, double) {
  using T = TestType;
  const T r1 = GENERATE(T(0), T(0.5), T(1.25));
  const T r2 = T(0.8);
  CAPTURE(r1);
  const Vec3<T> base(T(0.5), T(-1), T(0.25)), cap(T(-1), T(1.5), T(2));
  const Cone<T> c(base, r1, cap, r2, Material{}, 1);
  const Vec3<T> axis = glm::normalize(cap - base);
  const T height = glm::length(cap - base);
  const T slope = (r2 - r1) / height;
  // The distance to the slanted side in the plane through the axis is (R(y) − ρ)·cos α, cos α = 1/√(1 + k²).
  const test::Depth<T> depth = [&](const Vec3<T>& p) {
    const T y = glm::dot(p - base, axis);
    const T across = glm::length(p - base - y * axis);
    return glm::min((r1 + slope * y - across) / std::sqrt(1 + slope * slope), glm::min(y, height - y));
  };
  const auto bounds = c.bounds();
  REQUIRE(bounds);
  // A step of the sweep's margin against the normal stays inside except near the pointed apex and the rims,
  // where side and disk meet at an acute angle: there it can come out through the other face.
  const T margin = T(1e-3) * maxAbs(bounds->max - bounds->min);
  const test::Thick<T> thick = [&](const Vec3<T>& p) {
    const T y = glm::dot(p - base, axis);
    const T radius = r1 + slope * y;
    const T across = glm::length(p - base - y * axis);
    const bool nearRim = glm::min(y, height - y) < 2 * margin && radius - across < 2 * margin;
    return radius >= 2 * margin && !nearRim;
  };
  const auto seed = GENERATE(1u, 2u);
  test::sweep<T>(c, depth, bounds->min, bounds->max, seed, thick);
}

// Radii whose squares vanish in the arithmetic: the side's normal has no direction, so the side is missed
// (never a NaN point or normal).
TEMPLATE_TEST_CASE("cone: radii below the arithmetic's resolution give no NaN hit", "", float, double) {
  using T = TestType;
  const T tiny = std::is_same_v<T, float> ? T(1e-40) : T(1e-320);
  const Cone<T> c(Vec3<T>(0, -1, 0), tiny, Vec3<T>(0, 1, 0), T(0), Material{}, 1);
  CHECK_FALSE(shoot(c, Vec3<T>(0, 0, 5), Vec3<T>(0, 0, -1)));
}

TEMPLATE_TEST_CASE("an open cone has no end disks, and its inside is the solid's", "[cone]", float, double) {
  using T = TestType;
  // Radius 2 at y = 0 to radius 1 at y = 2.
  const Cone<T> c(Vec3<T>(0), T(2), Vec3<T>(0, 2, 0), T(1), Material{}, 1, true);
  CHECK_FALSE(c.intersect(Ray<T>{Vec3<T>(T(0.5), 5, 0), Vec3<T>(0, -1, 0)}, Interval<T>{}));
  // In through the top at x = 0.4 (a closed cone's cap there), out to the inner wall at (1.2, 1.6), where the
  // radius 2 − y/2 is 1.2; the normal still outward, tilted up by the slope.
  const T root5 = std::sqrt(T(5));
  const auto wall = c.intersect(Ray<T>{Vec3<T>(0, T(2.2), 0), Vec3<T>(2, -1, 0) / root5}, Interval<T>{});
  REQUIRE(wall);
  CHECK(wall->t == Approx(T(0.6) * root5));
  CHECK(wall->normal.x == Approx(2 / root5));
  CHECK(wall->normal.y == Approx(1 / root5));
  CHECK(c.inside(Vec3<T>(0, 1, 0)));
  CHECK_FALSE(c.inside(Vec3<T>(0, 3, 0)));
}
