// Up to four triangles of a leaf laid out lane by lane, tested against one ray at once in SIMD (as Embree's
// triangle4 leaves are; Wald, "Realtime Ray Tracing and Interactive Global Illumination", 2004, §7).
#pragma once

#include <cstdint>
#include <limits>

#include "raytrace/accel/lane_group.hpp"
#include "raytrace/geometry/interval.hpp"
#include "raytrace/geometry/ray.hpp"
#include "raytrace/shapes/triangle.hpp"

namespace rt {

// Up to kSize rays lane by lane (structure of arrays): what a test of one triangle against many rays reads.
template <class T> struct RayLanes {
  static constexpr int kSize = 16;
  alignas(64) T origin[3][kSize], dir[3][kSize], min[kSize], max[kSize];

  void set(int i, const Ray<T>& ray, Interval<T> range) {
    for (int a = 0; a < 3; ++a) origin[a][i] = ray.origin[a], dir[a][i] = ray.dir[a];
    min[i] = range.min, max[i] = range.max;
  }
};

// Aligned to a cache line: a group of floats (192 bytes) then spans three lines, not four.
template <class T> struct alignas(64) TriangleGroup : LaneGroup<T> {
  using typename LaneGroup<T>::Lanes;

  Lanes a[3]{}, ab[3]{}, ac[3]{};  // [axis]: lane k holds triangle k's vertex a and edges ab, ac

  // Lane `k` becomes the triangle t, which must not be degenerate (it would never be hit).
  void set(int k, const Triangle<T>& t, uint32_t index) {
    for (int axis = 0; axis < 3; ++axis) {
      a[axis][k] = t.a()[axis], ab[axis][k] = t.ab()[axis], ac[axis][k] = t.ac()[axis];
    }
    this->hold(k, index, t.id());
  }

  // The lanes whose triangle the ray meets strictly inside `range`, as bit k for lane k, with the hit's
  // distance in t[k]. Each lane does Triangle::solve's operations in its order, so a lane's answer and t have
  // the bits of solve()'s: only the early exits become masks.
  uint32_t hits(const Ray<T>& ray, Interval<T> range, Lanes& t) const {
    const Lanes d[3] = {Lanes{} + ray.dir.x, Lanes{} + ray.dir.y, Lanes{} + ray.dir.z};
    // p = d × ac, det = ab · p
    const Lanes p[3] = {d[1] * ac[2] - ac[1] * d[2], d[2] * ac[0] - ac[2] * d[0], d[0] * ac[1] - ac[0] * d[1]};
    const Lanes det = ab[0] * p[0] + ab[1] * p[1] + ab[2] * p[2];
    const Lanes s[3] = {ray.origin.x - a[0], ray.origin.y - a[1], ray.origin.z - a[2]};
    const Lanes u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
    // q = s × ab
    const Lanes q[3] = {s[1] * ab[2] - ab[1] * s[2], s[2] * ab[0] - ab[2] * s[0], s[0] * ab[1] - ab[0] * s[1]};
    const Lanes v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    t = (ac[0] * q[0] + ac[1] * q[1] + ac[2] * q[2]) / det;
    const auto met = (det != T(0)) & (u >= T(0)) & (u <= T(1)) & (v >= T(0)) & (u + v <= T(1)) & (range.min < t) &
                     (t < range.max);
    return this->bits(met);
  }

  // Every triangle of a group against the rays whose bits are set in `rays` at once, one lane per ray: bit i
  // of met[k] is set when ray i meets triangle k strictly inside [lanes.min[i], lanes.max[i]], at t[k][i]
  // (written for those rays only). Each lane does hits()' operations in their order, so the same bits.
  using ManyRays = void (*)(const TriangleGroup& group, const RayLanes<T>& lanes, uint32_t rays,
                            uint32_t (&met)[LaneGroup<T>::kSize], T (&t)[LaneGroup<T>::kSize][RayLanes<T>::kSize]);
  // The test of many rays, on processors with AVX-512 (16 rays of floats to a register); null elsewhere, and
  // for doubles.
  static ManyRays manyRays();
};
template <> TriangleGroup<float>::ManyRays TriangleGroup<float>::manyRays();
template <> TriangleGroup<double>::ManyRays TriangleGroup<double>::manyRays();

}  // namespace rt
