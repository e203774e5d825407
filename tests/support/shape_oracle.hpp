// Test support shared by the shape tests: an inside/outside oracle sweep and the hit-record checks that every
// shape must pass (the Object contract in object.hpp).
#pragma once

#include <cmath>
#include <functional>
#include <random>

#include <catch2/catch.hpp>

#include "raytrace/shapes/object.hpp"

namespace rt::test {

// How deep a point is inside the solid: positive inside, negative outside. Only the sign is trusted, and only
// beyond a margin, so a simple bound (not the exact distance) is enough.
template <class T> using Depth = std::function<T(const Vec3<T>&)>;
// Whether the solid is thick enough at a surface point for a step of the sweep's margin against the normal to
// stay inside (false near an acute edge or a pointed apex, where such a step can come out through another face).
template <class T> using Thick = std::function<bool(const Vec3<T>&)>;

template <class T> bool isFinite(const Vec3<T>& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The contract of a hit: finite, the point on the ray, the normal unit and outward (a step along it leaves
// the solid, a step against it enters).
template <class T>
void checkHit(const Object<T>& object, const Ray<T>& ray, const Hit<T>& hit, const Depth<T>& depth, T margin,
              const Thick<T>& thick = {}) {
  CAPTURE(hit.t, hit.point.x, hit.point.y, hit.point.z, hit.normal.x, hit.normal.y, hit.normal.z);
  REQUIRE(std::isfinite(hit.t));
  REQUIRE(isFinite(hit.point));
  REQUIRE(isFinite(hit.normal));
  CHECK(hit.object == &object);
  CHECK(glm::length(hit.normal) == Approx(1).epsilon(1e-5));
  CHECK(glm::length(hit.point - ray.at(hit.t)) < margin);
  CHECK(depth(hit.point + margin * hit.normal) < T(0));
  if (!thick || thick(hit.point)) CHECK(depth(hit.point - margin * hit.normal) > T(0));
}

// A seeded sweep of rays from a grid of origins around the solid (inside and out), each aimed at a random
// target. Samples along the ray before the reported hit (or along the whole ray on a miss) must not be clearly
// inside when the ray starts outside, or clearly outside when it starts inside; a ray aimed at a clearly inside
// point from outside must hit before reaching it.
template <class T>
void sweep(const Object<T>& object, const Depth<T>& depth, const Vec3<T>& lo, const Vec3<T>& hi, unsigned seed,
           const Thick<T>& thick = {}) {
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<T> unit(T(0), T(1));
  const Vec3<T> size = hi - lo;
  const T margin = T(1e-3) * maxAbs(size);
  const auto randomIn = [&](const Vec3<T>& a, const Vec3<T>& b) {
    return a + Vec3<T>(unit(rng), unit(rng), unit(rng)) * (b - a);
  };
  constexpr int kGrid = 6, kSamples = 400;
  for (int i = 0; i < kGrid * kGrid * kGrid; ++i) {
    const Vec3<T> cell(i % kGrid, (i / kGrid) % kGrid, i / (kGrid * kGrid));
    const Vec3<T> origin = lo - size + (cell + T(0.5)) * (T(3) / kGrid) * size;  // a 3× wider grid
    const T start = depth(origin);
    if (std::abs(start) < margin) continue;  // on the surface: either answer is right
    const Vec3<T> target = randomIn(lo - T(0.2) * size, hi + T(0.2) * size);
    const Ray<T> ray{origin, glm::normalize(target - origin)};
    CAPTURE(origin.x, origin.y, origin.z, target.x, target.y, target.z);
    const auto hit = object.intersect(ray, Interval<T>{});
    const T reach = hit ? hit->t : glm::length(target - origin) + T(2) * maxAbs(size);
    for (int k = 1; k < kSamples; ++k) {
      const T d = depth(ray.at(reach * k / kSamples));
      if (start > 0) CHECK_FALSE(d < -margin);
      else CHECK_FALSE(d > margin);
    }
    if (hit) checkHit(object, ray, *hit, depth, margin, thick);
    if (start < 0 && depth(target) > margin) {
      REQUIRE(hit);
      CHECK(hit->t <= glm::length(target - origin));
    }
  }
}

// A seeded sweep of rays through a box around the shape, each from a random point up to twice as far out: the
// hits found one after another (each next one asked for beyond the last) are the surface's crossings, so
// inside() must keep its answer between two of them and change it across each. Samples within `margin` of a
// crossing are left out.
template <class T>
void paritySweep(const Object<T>& object, const Vec3<T>& lo, const Vec3<T>& hi, T margin, unsigned seed,
                 int rays = 2000) {
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<T> unit(T(0), T(1));
  const Vec3<T> size = hi - lo;
  const auto randomIn = [&](const Vec3<T>& a, const Vec3<T>& b) {
    return a + Vec3<T>(unit(rng), unit(rng), unit(rng)) * (b - a);
  };
  for (int r = 0; r < rays; ++r) {
    const Vec3<T> origin = randomIn(lo - size, hi + size), target = randomIn(lo, hi);
    const Ray<T> ray{origin, glm::normalize(target - origin)};
    const T end = T(2) * glm::length(target - origin);
    CAPTURE(origin.x, origin.y, origin.z, target.x, target.y, target.z);
    bool in = object.inside(origin);
    T from = 0;
    for (int crossing = 0; crossing < 16 && from < end; ++crossing) {
      const auto hit = object.intersect(ray, Interval<T>{from, end});
      const T to = hit ? hit->t : end;
      for (int k = 1; k < 8; ++k) {
        const T t = from + (to - from) * T(k) / T(8);
        if (t - from > margin && to - t > margin) CHECK(object.inside(ray.at(t)) == in);
      }
      if (!hit) break;
      from = to;
      in = !in;
    }
  }
}

}  // namespace rt::test
