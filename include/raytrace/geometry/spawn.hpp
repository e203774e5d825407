// The one self-intersection policy: every ray that starts on a surface (shadow, reflection, refraction) is
// made here, and nowhere else is an epsilon chosen (docs/reference/stability.md F3–F6).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "raytrace/geometry/hit.hpp"
#include "raytrace/geometry/interval.hpp"
#include "raytrace/geometry/ray.hpp"

namespace rt {

enum class OffsetPolicy {
  // Move the re-projected hit point along the normal, to the side the ray leaves by, by kRayEpsilon
  // relative to the point's magnitude (Mitsuba 3 `offset_p`; docs/reference/stability.md F4a). Zero re-hits at any scale.
  Relative,
  // The course reference's P ± 0.001·N: 0.001 along the normal, to the side the ray leaves by (the 2018
  // reference renderer that made the p5 images; the course tier's offset, scene/arithmetic.hpp). Fails once the
  // coordinates' rounding nears 0.001 or a feature is thinner than it (docs/reference/stability.md F4, F5; the tier's
  // domain, chooseArithmetic()). An earlier reference (2018-05-17) moved along the ray instead, P + 0.001·d
  // (docs/reference/csc473.md §c.8): the p3/p4 printrays texts were made by it and now differ in their 4th decimals
  // (optional tests).
  Course,
  // A fixed 1e-4 along the normal, the other common epsilon. Fails once ulp(|p|) exceeds it (|p| ≳ 1e3 in
  // float, docs/reference/stability.md F4); for the chart only.
  FixedNormal,
  // Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection" (Ray Tracing Gems ch. 6):
  // 256 ulps per unit of normal component, added to the coordinates' bits, and 1/65536 absolute near the
  // origin (|x| < 1/32) where ulps vanish (docs/reference/stability.md F4b). For the chart; ~10× Relative's offset.
  WaechterBinder,
};

template <class T> constexpr T kRayEpsilon = T(16) * std::numeric_limits<T>::epsilon();
constexpr double kCourseEpsilon = 0.001;
constexpr double kFixedNormalEpsilon = 1e-4;
// Shadow segments stop this fraction short of the light, so a light on a surface does not shadow itself.
template <class T> constexpr T kShadowEpsilon = T(64) * std::numeric_limits<T>::epsilon();

// Wächter–Binder's offset of p along n (RTG ch. 6, `offset_ray`), for float and double: n's components in
// units of 256 ulps move each coordinate through its bit pattern, so the step scales with |x| exactly; below
// |x| = 1/32 a fixed step of 128ε (2^-16 in float, as in the paper) takes over.
template <class T> Vec3<T> waechterBinderOffset(const Vec3<T>& p, const Vec3<T>& n) {
  using Bits = std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>;
  Vec3<T> out;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(p[i]) < T(1) / T(32)) {
      out[i] = p[i] + T(128) * std::numeric_limits<T>::epsilon() * n[i];
      continue;
    }
    const Bits step = Bits(T(256) * n[i]);
    Bits bits;
    std::memcpy(&bits, &p[i], sizeof bits);
    bits += p[i] < T(0) ? -step : step;
    std::memcpy(&out[i], &bits, sizeof bits);
  }
  return out;
}

// The origin of a ray leaving `hit` in direction `dir`. Forced inline: GCC kept a call per shadow and
// secondary ray (docs/performance-notes.md, "Whitted path").
template <class T> [[gnu::always_inline]] inline Vec3<T> spawnOrigin(const Hit<T>& hit, const Vec3<T>& dir, OffsetPolicy policy) {
  const Vec3<T> outward = glm::dot(hit.normal, dir) > T(0) ? hit.normal : -hit.normal;
  switch (policy) {
    case OffsetPolicy::Course:
      return hit.point + T(kCourseEpsilon) * outward;
    case OffsetPolicy::FixedNormal:
      return hit.point + T(kFixedNormalEpsilon) * outward;
    case OffsetPolicy::WaechterBinder:
      return waechterBinderOffset(hit.point, outward);
    case OffsetPolicy::Relative:
      break;
  }
  return hit.point + kRayEpsilon<T> * std::max(T(1), maxAbs(hit.point)) * outward;
}

// Whether a hit at t on a surface of normal n lies across that surface within a few offsets of the ray's start:
// the surface a spawned ray leaves, found again by a shape whose roots carry more rounding than the offset
// (prism, lathe, sor), rather than a new one.
inline bool nearSpawnOffset(double t, const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& n) {
  return std::abs(t * glm::dot(d, n)) <= 4 * kRayEpsilon<double> * std::max(1.0, maxAbs(o));
}

template <class T> Ray<T> spawnRay(const Hit<T>& hit, const Vec3<T>& dir, OffsetPolicy policy) {
  return Ray<T>{spawnOrigin(hit, dir, policy), dir};
}

// A ray from `hit` toward `target` with the interval that ends just before it: the shadow segment. The
// direction from the hit point picks the side to leave by. The course reference then aims from its offset
// origin, so its ray reaches the target itself; the other policies keep that direction, a ray parallel to the
// one from the hit point: aimed from its origin at a target nearer the surface than the origin, it would
// run back down to the surface, and scale-aware offsets are too small for that (tests/geometry/test_stability_spawn.cpp
// counts it). `dir` is normalize(target − hit.point) and `side` a vector on the side of the surface to leave
// by: `dir` itself, or a shading normal already known to face the target, which lets the origin be found
// without waiting for dir's square root. The ray and segment are written in place: the tracer makes one for
// every hit and light.
template <class T>
void spawnRayTo(const Hit<T>& hit, const Vec3<T>& target, const Vec3<T>& dir, const Vec3<T>& side,
                OffsetPolicy policy, Ray<T>& ray, Interval<T>& segment) {
  ray.origin = spawnOrigin(hit, side, policy);
  const Vec3<T> toTarget = target - ray.origin;
  const T distance = glm::length(toTarget);
  // glm::normalize(toTarget) with the square root already taken: the same bits.
  ray.dir = policy == OffsetPolicy::Course ? toTarget * (T(1) / distance) : dir;
  segment = {T(0), distance * (T(1) - kShadowEpsilon<T>)};
}

template <class T>
std::pair<Ray<T>, Interval<T>> spawnRayTo(const Hit<T>& hit, const Vec3<T>& target, OffsetPolicy policy) {
  const Vec3<T> dir = glm::normalize(target - hit.point);
  std::pair<Ray<T>, Interval<T>> out;
  spawnRayTo(hit, target, dir, dir, policy, out.first, out.second);
  return out;
}

}  // namespace rt
