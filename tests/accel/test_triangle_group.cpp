#include <catch2/catch.hpp>

#include <cstring>
#include <limits>
#include <random>

#include "raytrace/accel/triangle_group.hpp"

namespace {

const rt::Material kMaterial;

template <class T> rt::Vec3<T> randomPoint(std::mt19937& rng, double extent) {
  std::uniform_real_distribution<double> pos(-extent, extent);
  return rt::Vec3<T>(pos(rng), pos(rng), pos(rng));
}

// A triangle of the sweep: most at random, some lying in the plane z = 1 (so that a ray with dir.z = 0 is
// exactly parallel, det = 0), some thin slivers; none degenerate.
template <class T> rt::Triangle<T> randomTriangle(std::mt19937& rng, int id) {
  for (;;) {
    rt::Vec3<T> a = randomPoint<T>(rng, 4), b = randomPoint<T>(rng, 4), c = randomPoint<T>(rng, 4);
    if (id % 4 == 1) a.z = b.z = c.z = T(1);
    if (id % 4 == 2) c = a + (b - a) * T(0.5) + randomPoint<T>(rng, 1e-3);
    rt::Triangle<T> t(a, b, c, kMaterial, id);
    if (!t.degenerate()) return t;
  }
}

// A ray toward the triangle: at a vertex, a point of an edge, an inside point or anywhere; some parallel to the
// plane z = 1.
template <class T> rt::Ray<T> rayToward(std::mt19937& rng, const rt::Triangle<T>& t, int kind) {
  std::uniform_real_distribution<double> unit(0, 1);
  const T s = T(unit(rng)), r = T(unit(rng));
  const rt::Vec3<T> targets[] = {t.a(), t.a() + t.ab(), t.a() + t.ac(), t.a() + s * t.ab(),
                                 t.a() + t.ab() + s * (t.ac() - t.ab()), t.a() + s * t.ab() + (1 - s) * r * t.ac(),
                                 randomPoint<T>(rng, 4)};
  const rt::Vec3<T> origin = randomPoint<T>(rng, 10);
  rt::Ray<T> ray{origin, targets[kind % 7] - origin};
  if (kind % 5 == 4) ray.dir.z = T(0), ray.origin.z = kind % 2 ? T(1) : T(0.5);
  return ray;
}

// A group of `used` triangles of the sweep (randomTriangle), lane k holding triangles[k] as object 10 + k.
template <class T>
rt::TriangleGroup<T> randomGroup(std::mt19937& rng, int trial, int used, std::vector<rt::Triangle<T>>& triangles) {
  rt::TriangleGroup<T> group;
  for (int k = 0; k < used; ++k) {
    triangles.push_back(randomTriangle<T>(rng, trial + k));
    group.set(k, triangles.back(), uint32_t(10 + k));
  }
  return group;
}

}  // namespace

TEMPLATE_TEST_CASE("each lane of a triangle group gives Triangle::solve's answer and bits", "[bvh]", float, double) {
  using T = TestType;
  std::mt19937 rng(2024);
  int hits = 0, boundary = 0;  // lanes hit, and hits on an edge or vertex (u, v or u + v exactly 0 or 1)
  for (int trial = 0; trial < 20000; ++trial) {
    CAPTURE(trial);
    const int used = 1 + trial % rt::TriangleGroup<T>::kSize;
    std::vector<rt::Triangle<T>> triangles;
    const rt::TriangleGroup<T> group = randomGroup<T>(rng, trial, used, triangles);
    const rt::Ray<T> ray = rayToward<T>(rng, triangles[size_t(trial) % triangles.size()], trial / 4);
    rt::Interval<T> range{T(0), std::numeric_limits<T>::infinity()};
    T tAny, u, v;
    // Some ranges end exactly at the hit's t (excluded) or start there.
    if (trial % 3 && rt::Triangle<T>::solve(triangles[0].a(), triangles[0].ab(), triangles[0].ac(), ray, range, tAny,
                                            u, v)) {
      if (trial % 3 == 1) range.max = tAny;
      if (trial % 6 == 2) range.min = tAny;
    }
    typename rt::TriangleGroup<T>::Lanes t;
    const uint32_t met = group.hits(ray, range, t);
    CHECK(met >> used == 0);
    for (int k = 0; k < used; ++k) {
      CAPTURE(k);
      const rt::Triangle<T>& tri = triangles[size_t(k)];
      T expected;
      const bool hit = rt::Triangle<T>::solve(tri.a(), tri.ab(), tri.ac(), ray, range, expected, u, v);
      REQUIRE(bool(met >> k & 1) == hit);
      const T lane = t[k];  // a copy: clang gives no address of a vector element
      if (hit) REQUIRE(std::memcmp(&lane, &expected, sizeof(T)) == 0);
      hits += hit;
      boundary += hit && (u == T(0) || v == T(0) || u + v == T(1));
      CHECK(group.object[k] == uint32_t(10 + k));
      CHECK(group.id[k] == tri.id());
    }
  }
  CHECK(hits > 5000);
  CHECK(boundary > 500);
}

TEST_CASE("the test of many rays at once gives each ray Triangle::solve's answer and bits", "[bvh]") {
  using T = float;
  constexpr int kRays = rt::RayLanes<T>::kSize;
  const auto manyRays = rt::TriangleGroup<T>::manyRays();
  __builtin_cpu_init();
  REQUIRE(bool(manyRays) == bool(__builtin_cpu_supports("avx512f")));
  if (!manyRays) return;
  REQUIRE(rt::TriangleGroup<double>::manyRays() == nullptr);
  std::mt19937 rng(7);
  int hits = 0, boundary = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    CAPTURE(trial);
    const int used = 1 + trial % rt::TriangleGroup<T>::kSize;
    std::vector<rt::Triangle<T>> triangles;
    const rt::TriangleGroup<T> group = randomGroup<T>(rng, trial, used, triangles);
    // Rays toward the group's triangles, some ranges ending or starting exactly at a hit; a random subset asked.
    rt::RayLanes<T> lanes;
    rt::Ray<T> rays[kRays];
    rt::Interval<T> ranges[kRays];
    for (int i = 0; i < kRays; ++i) {
      const rt::Triangle<T>& aim = triangles[size_t(i) % triangles.size()];
      rays[i] = rayToward<T>(rng, aim, int(rng() % 35));
      ranges[i] = {T(0), std::numeric_limits<T>::infinity()};
      T t, u, v;
      if (i % 3 && rt::Triangle<T>::solve(aim.a(), aim.ab(), aim.ac(), rays[i], ranges[i], t, u, v)) {
        (i % 3 == 1 ? ranges[i].max : ranges[i].min) = t;
      }
      lanes.set(i, rays[i], ranges[i]);
    }
    const uint32_t asked = trial % 5 ? uint32_t(rng()) & 0xffff : 0xffff;
    uint32_t met[rt::TriangleGroup<T>::kSize];
    T t[rt::TriangleGroup<T>::kSize][kRays];
    manyRays(group, lanes, asked, met, t);
    for (int k = 0; k < rt::TriangleGroup<T>::kSize; ++k) {
      CAPTURE(k);
      for (int i = 0; i < kRays; ++i) {
        CAPTURE(i);
        T expected = 0, u = 0, v = 0;
        const bool hit = k < used && (asked >> i & 1) &&
                         rt::Triangle<T>::solve(triangles[size_t(k)].a(), triangles[size_t(k)].ab(),
                                                triangles[size_t(k)].ac(), rays[i], ranges[i], expected, u, v);
        REQUIRE(bool(met[k] >> i & 1) == hit);
        if (hit) REQUIRE(std::memcmp(&t[k][i], &expected, sizeof(T)) == 0);
        hits += hit;
        boundary += hit && (u == T(0) || v == T(0) || u + v == T(1));
      }
    }
  }
  CHECK(hits > 3000);
  CHECK(boundary > 300);
}
