#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "raytrace/shapes/cylinder.hpp"
#include "shape_oracle.hpp"

using namespace rt;

namespace {

// Radius 1 around the y axis from y = 0 to y = 2.
template <class T> Cylinder<T> upright() { return Cylinder<T>(Vec3<T>(0), Vec3<T>(0, 2, 0), T(1), Material{}, 1); }

template <class T> std::optional<Hit<T>> shoot(const Cylinder<T>& c, const Vec3<T>& origin, const Vec3<T>& dir) {
  return c.intersect(Ray<T>{origin, dir}, Interval<T>{});
}

}  // namespace

TEMPLATE_TEST_CASE("a ray across the axis hits the side", "[cylinder]", float, double) {
  using T = TestType;
  const auto hit = shoot(upright<T>(), Vec3<T>(5, 1, 0), Vec3<T>(-1, 0, 0));
  REQUIRE(hit);
  CHECK(hit->t == T(4));
  CHECK(hit->point == Vec3<T>(1, 1, 0));
  CHECK(hit->normal == Vec3<T>(1, 0, 0));
}

TEMPLATE_TEST_CASE("a ray along the axis meets only the end disks", "[cylinder]", float, double) {
  using T = TestType;
  const Cylinder<T> c = upright<T>();
  const auto top = shoot(c, Vec3<T>(T(0.5), 5, 0), Vec3<T>(0, -1, 0));
  REQUIRE(top);
  CHECK(top->t == T(3));
  CHECK(top->point == Vec3<T>(T(0.5), 2, 0));
  CHECK(top->normal == Vec3<T>(0, 1, 0));
  const auto bottom = shoot(c, Vec3<T>(T(0.5), -5, T(-0.5)), Vec3<T>(0, 1, 0));
  REQUIRE(bottom);
  CHECK(bottom->t == T(5));
  CHECK(bottom->normal == Vec3<T>(0, -1, 0));
  CHECK_FALSE(shoot(c, Vec3<T>(T(1.5), 5, 0), Vec3<T>(0, -1, 0)));
}

TEMPLATE_TEST_CASE("from inside, the exit has the outward normal", "[cylinder]", float, double) {
  using T = TestType;
  const Cylinder<T> c = upright<T>();
  const auto down = shoot(c, Vec3<T>(T(0.5), 1, 0), Vec3<T>(0, -1, 0));
  REQUIRE(down);
  CHECK(down->t == T(1));
  CHECK(down->normal == Vec3<T>(0, -1, 0));
  const auto side = shoot(c, Vec3<T>(0, 1, 0), Vec3<T>(0, 0, 1));
  REQUIRE(side);
  CHECK(side->t == T(1));
  CHECK(side->normal == Vec3<T>(0, 0, 1));
}

TEMPLATE_TEST_CASE("the rim has no crack", "[cylinder]", float, double) {
  using T = TestType;
  const Cylinder<T> c = upright<T>();
  // Along the side line x = 1: the cap disk's bound is inclusive, so the rim point is hit, re-projected
  // the rim margin (8ε·(|base| + height + radius) = 24ε) inside the edge (docs/reference/stability.md F6).
  const auto along = shoot(c, Vec3<T>(1, 5, 0), Vec3<T>(0, -1, 0));
  REQUIRE(along);
  CHECK(along->t == T(3));
  CHECK(along->normal == Vec3<T>(0, 1, 0));
  CHECK(glm::length(along->point - Vec3<T>(1, 2, 0)) <= 25 * std::numeric_limits<T>::epsilon());
  CHECK(along->point.x < T(1));
  // Across the axis exactly at the heights of the ends: the side's height bound is inclusive.
  for (const T y : {T(0), T(2)}) {
    const auto across = shoot(c, Vec3<T>(5, y, 0), Vec3<T>(-1, 0, 0));
    REQUIRE(across);
    CHECK(across->t == T(4));
    CHECK(across->normal == Vec3<T>(1, 0, 0));
  }
  // Diagonally through the rim point (1, 2, 0): side or cap, at the rim.
  const auto diagonal = shoot(c, Vec3<T>(3, 4, 0), glm::normalize(Vec3<T>(-1, -1, 0)));
  REQUIRE(diagonal);
  CHECK(diagonal->t == Approx(2 * std::sqrt(2.0)).epsilon(1e-6));
  CHECK(glm::length(diagonal->point - Vec3<T>(1, 2, 0)) < T(1e-5));
}

// docs/reference/stability.md T6: d ∝ (δ, ±1, 0), origin inside or outside the radius; and d.y = 0 below, at and above
// an end.
TEMPLATE_TEST_CASE("rays nearly parallel to the axis give finite t", "[cylinder]", float, double) {
  using T = TestType;
  const Cylinder<T> c = upright<T>();
  const T delta = GENERATE(T(0), T(1e-20), T(1e-12), T(1e-7), T(1e-4));
  const T sign = GENERATE(T(-1), T(1));
  CAPTURE(delta, sign);
  const Vec3<T> dir = glm::normalize(Vec3<T>(delta, sign, 0));
  const Vec3<T> inside(T(0.3), T(1) - sign * 5, 0), outside(3, T(1) - sign * 5, 0);
  const auto hit = shoot(c, inside, dir);
  REQUIRE(hit);
  REQUIRE(std::isfinite(hit->t));
  // The end disk at distance 4 along the axis, at t = 4/|dir.y|.
  CHECK(hit->t == Approx(T(4) / std::abs(dir.y)).epsilon(1e-6));
  CHECK(hit->normal == Vec3<T>(0, -sign, 0));
  CHECK_FALSE(shoot(c, outside, dir));
  // From inside the solid.
  const auto exit = shoot(c, Vec3<T>(T(0.3), 1, 0), dir);
  REQUIRE(exit);
  CHECK(exit->t == Approx(T(1) / std::abs(dir.y)).epsilon(1e-6));
  CHECK(exit->normal == Vec3<T>(0, sign, 0));
}

TEMPLATE_TEST_CASE("rays across the axis below, at and above the ends hit only the side", "[cylinder]", float,
                   double) {
  using T = TestType;
  const Cylinder<T> c = upright<T>();
  for (const T y : {T(-0.5), T(0), T(1), T(2), T(2.5)}) {
    CAPTURE(y);
    const auto hit = shoot(c, Vec3<T>(0, y, 5), Vec3<T>(0, 0, -1));
    CHECK(bool(hit) == (y >= 0 && y <= 2));
    if (hit) {
      CHECK(hit->t == T(4));
      CHECK(hit->normal == Vec3<T>(0, 0, 1));
    }
  }
}

TEMPLATE_TEST_CASE("a cylinder along any axis", "[cylinder]", float, double) {
  using T = TestType;
  // Around the x axis; and around the diagonal (1, 1, 0) from the origin to (2, 2, 0).
  const Cylinder<T> lying(Vec3<T>(-1, 0, 0), Vec3<T>(1, 0, 0), T(0.5), Material{}, 1);
  const auto top = shoot(lying, Vec3<T>(T(0.25), 3, 0), Vec3<T>(0, -1, 0));
  REQUIRE(top);
  CHECK(top->t == T(2.5));
  CHECK(top->normal == Vec3<T>(0, 1, 0));
  const auto end = shoot(lying, Vec3<T>(3, T(0.25), 0), Vec3<T>(-1, 0, 0));
  REQUIRE(end);
  CHECK(end->t == T(2));
  CHECK(end->normal == Vec3<T>(1, 0, 0));

  const Cylinder<T> diagonal(Vec3<T>(0), Vec3<T>(2, 2, 0), T(1), Material{}, 1);
  const auto side = shoot(diagonal, Vec3<T>(1, 1, 5), Vec3<T>(0, 0, -1));
  REQUIRE(side);
  CHECK(side->t == Approx(4).epsilon(1e-6));
  CHECK(side->normal.z == Approx(1).epsilon(1e-6));
  const auto cap = shoot(diagonal, Vec3<T>(5, 5, 0), glm::normalize(Vec3<T>(-1, -1, 0)));
  REQUIRE(cap);
  CHECK(cap->t == Approx(3 * std::sqrt(2.0)).epsilon(1e-6));
  CHECK(glm::length(cap->normal - glm::normalize(Vec3<T>(1, 1, 0))) < T(1e-6));
}

TEMPLATE_TEST_CASE("cylinder bounds are tight for any axis", "[cylinder]", float, double) {
  using T = TestType;
  const auto upright_ = upright<T>().bounds();
  REQUIRE(upright_);
  CHECK(upright_->min == Vec3<T>(-1, 0, -1));
  CHECK(upright_->max == Vec3<T>(1, 2, 1));
  const auto diagonal = Cylinder<T>(Vec3<T>(0), Vec3<T>(2, 2, 0), T(1), Material{}, 1).bounds();
  REQUIRE(diagonal);
  const T reach = std::sqrt(T(0.5));
  CHECK(glm::length(diagonal->min - Vec3<T>(-reach, -reach, -1)) < T(1e-6));
  CHECK(glm::length(diagonal->max - Vec3<T>(2 + reach, 2 + reach, 1)) < T(1e-6));
}

TEMPLATE_TEST_CASE("cylinder sweep against the inside/outside oracle", "[cylinder]", float, double) {
  using T = TestType;
  const Vec3<T> base(T(0.5), T(-1), T(0.25)), cap(T(-1), T(1.5), T(2));
  const T radius = T(0.75);
  const Cylinder<T> c(base, cap, radius, Material{}, 1);
  const Vec3<T> axis = glm::normalize(cap - base);
  const T height = glm::length(cap - base);
  const test::Depth<T> depth = [&](const Vec3<T>& p) {
    const T y = glm::dot(p - base, axis);
    const T across = glm::length(p - base - y * axis);
    return glm::min(radius - across, glm::min(y, height - y));
  };
  const auto bounds = c.bounds();
  REQUIRE(bounds);
  const auto seed = GENERATE(1u, 2u, 3u);
  test::sweep<T>(c, depth, bounds->min, bounds->max, seed);
}

// A radius whose square vanishes in the arithmetic: the side's normal has no direction, so the side is missed
// (never a NaN point or normal).
TEMPLATE_TEST_CASE("cylinder: a radius below the arithmetic's resolution gives no NaN hit", "", float, double) {
  using T = TestType;
  const T tiny = std::is_same_v<T, float> ? T(1e-40) : T(1e-320);
  const Cylinder<T> c(Vec3<T>(0), Vec3<T>(0, 2, 0), tiny, Material{}, 1);
  CHECK_FALSE(shoot(c, Vec3<T>(0, 1, 5), Vec3<T>(0, 0, -1)));
}

TEMPLATE_TEST_CASE("an open cylinder has no end disks, and its inside is the solid's", "[cylinder]", float, double) {
  using T = TestType;
  const Cylinder<T> c(Vec3<T>(0), Vec3<T>(0, 2, 0), T(1), Material{}, 1, true);
  // Along the axis, through both open ends: nothing.
  CHECK_FALSE(shoot(c, Vec3<T>(T(0.5), 5, 0), Vec3<T>(0, -1, 0)));
  // Slanting in through the top: the inner wall, its normal still outward.
  const auto wall = shoot(c, Vec3<T>(0, 3, 0), Vec3<T>(3, -4, 0) / T(5));
  REQUIRE(wall);
  CHECK(wall->t == Approx(T(5) / 3));
  CHECK(wall->normal == Vec3<T>(1, 0, 0));
  // Across: both sides, as a closed one.
  const auto side = shoot(c, Vec3<T>(5, 1, 0), Vec3<T>(-1, 0, 0));
  REQUIRE(side);
  CHECK(side->t == T(4));
  // POV-Ray's picture of an open cylinder intersected with a sphere shows the sphere inside the tube.
  CHECK(c.inside(Vec3<T>(0, 1, 0)));
  CHECK_FALSE(c.inside(Vec3<T>(0, 3, 0)));
}
