// Ray-plane intersection: hits from both sides, parallel rays in and off the plane, the open interval.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "raytrace/shapes/plane.hpp"

namespace {

template <class T> rt::Plane<T> floorAt(T height) {
  return rt::Plane<T>(rt::Vec3<T>(0, 1, 0), height, rt::Material{}, 1);
}

}  // namespace

TEMPLATE_TEST_CASE("plane: hits from above and below; the normal is the plane's own", "", float, double) {
  using T = TestType;
  const auto plane = floorAt<T>(-4);
  const auto above = plane.intersect({{1, 0, 2}, {0, -1, 0}}, {});
  REQUIRE(above);
  CHECK(above->t == T(4));
  CHECK(above->point == rt::Vec3<T>(1, -4, 2));
  CHECK(above->normal == rt::Vec3<T>(0, 1, 0));
  CHECK(above->object == &plane);
  CHECK(above->frontFace(rt::Vec3<T>(0, -1, 0)));
  const auto below = plane.intersect({{0, -10, 0}, {0, 1, 0}}, {});
  REQUIRE(below);
  CHECK(below->t == T(6));
  CHECK(below->normal == rt::Vec3<T>(0, 1, 0));
  CHECK_FALSE(below->frontFace(rt::Vec3<T>(0, 1, 0)));
  CHECK_FALSE(plane.bounds());
}

TEMPLATE_TEST_CASE("plane: the course's firsthit on simple.pov's floor (p1 T = 24.4800)", "", float, double) {
  using T = TestType;
  // Pixel (320, 160) of simple.pov: the ray below the sphere meets the plane y = -4 at t = 4 / 0.16339892…
  const rt::Vec3<T> dir(T(0.0010276636232874991), T(-0.16339892460003322), T(-0.9865595447549174));
  const auto hit = floorAt<T>(-4).intersect({{0, 0, 14}, dir}, {});
  REQUIRE(hit);
  CHECK(double(hit->t) == Approx(4 / 0.16339892460003322).epsilon(1e-6));
  CHECK(double(hit->point.y) == Approx(-4).epsilon(1e-6));
}

TEMPLATE_TEST_CASE("plane: oblique normals", "", float, double) {
  using T = TestType;
  const rt::Vec3<T> n = glm::normalize(rt::Vec3<T>(1, 1, 0));
  const rt::Plane<T> plane(n, std::sqrt(T(2)), rt::Material{}, 1);  // through (1, 1, 0)
  const auto hit = plane.intersect({{0, 0, 5}, n}, {});
  REQUIRE(hit);
  CHECK(hit->t == Approx(std::sqrt(T(2))));
  CHECK(double(glm::dot(n, hit->point)) == Approx(std::sqrt(2.0)));
}

TEMPLATE_TEST_CASE("plane: parallel rays never hit, in the plane or off it, on either side", "", float, double) {
  using T = TestType;
  const auto plane = floorAt<T>(-4);
  for (const T y : {T(-4), T(0), T(-8)}) {
    CAPTURE(y);
    CHECK_FALSE(plane.intersect({{0, y, 0}, {1, 0, 0}}, {}));
    CHECK_FALSE(plane.intersect({{0, y, 0}, glm::normalize(rt::Vec3<T>(1, 0, 1))}, {}));
  }
}

TEMPLATE_TEST_CASE("plane: the interval is open and pointing away misses", "", float, double) {
  using T = TestType;
  const auto plane = floorAt<T>(0);
  const rt::Ray<T> down{{0, 2, 0}, {0, -1, 0}};
  CHECK_FALSE(plane.intersect({{0, 2, 0}, {0, 1, 0}}, {}));    // t = −2
  CHECK_FALSE(plane.intersect(down, {T(0), T(2)}));            // t = 2 is the end, excluded
  CHECK(plane.intersect(down, {T(0), T(2.001)}));
  CHECK_FALSE(plane.intersect(down, {T(2), T(10)}));           // and so is the start
  CHECK_FALSE(plane.intersect({{0, 0, 0}, {0, -1, 0}}, {}));   // origin on the plane: t = 0 is outside (0, ∞)
}

TEMPLATE_TEST_CASE("plane: the hit point is re-projected onto the plane", "", float, double) {
  using T = TestType;
  const auto plane = floorAt<T>(-4);
  // A grazing ray from far away: ray.at(t) would miss the plane by many ulps; the hit point does not.
  const rt::Vec3<T> dir = glm::normalize(rt::Vec3<T>(1000, -1, 0.3));
  const auto hit = plane.intersect({{-3000, -1, 7}, dir}, {});
  REQUIRE(hit);
  CHECK(hit->point.y == T(-4));
}

TEMPLATE_TEST_CASE("plane: a packet's tests answer as its rays' own tests do", "", float, double) {
  using T = TestType;
  constexpr int kRays = 32;
  const rt::Vec3<T> n = glm::normalize(rt::Vec3<T>(1, 3, -2));
  const rt::Plane<T> plane(n, T(0.5), rt::Material{}, 2);
  const rt::Plane<T> earlier(rt::Vec3<T>(0, 1, 0), T(-1), rt::Material{}, 1);  // gives some rays a hit first
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-3, 3), unit(0, 1);
  std::normal_distribution<double> normal;
  for (int round = 0; round < 200; ++round) {
    CAPTURE(round);
    rt::Ray<T> rays[kRays];
    rt::Interval<T> ranges[kRays];
    std::optional<rt::Hit<T>> mine[kRays], theirs[kRays];
    for (int i = 0; i < kRays; ++i) {
      rt::Vec3<T> dir(glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng))));
      // A quarter of the rays run parallel to the plane, half of those in it.
      if (i % 4 == 0) dir = glm::normalize(glm::cross(dir, n));
      const rt::Vec3<T> origin = i % 8 == 0 ? T(0.5) * n : rt::Vec3<T>(pos(rng), pos(rng), pos(rng));
      rays[i] = {origin, dir};
      ranges[i] = {T(0), unit(rng) < 0.5 ? T(unit(rng) * 4) : std::numeric_limits<T>::infinity()};
      if (unit(rng) < 0.5) mine[i] = theirs[i] = earlier.intersect(rays[i], {});
    }
    plane.closerHits(rays, kRays, {}, mine);
    plane.rt::Object<T>::closerHits(rays, kRays, {}, theirs);  // intersect() ray by ray
    for (int i = 0; i < kRays; ++i) {
      CAPTURE(i);
      REQUIRE(bool(mine[i]) == bool(theirs[i]));
      if (!mine[i]) continue;
      CHECK(mine[i]->t == theirs[i]->t);
      CHECK(mine[i]->object == theirs[i]->object);
      CHECK(mine[i]->point == theirs[i]->point);
    }
    const uint32_t open = uint32_t(rng());
    CHECK(plane.occludes(rays, ranges, open) == plane.rt::Object<T>::occludes(rays, ranges, open));
  }
}
