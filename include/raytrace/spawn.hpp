// The one self-intersection policy: every ray that starts on a surface (shadow, reflection, refraction) is
// made here, and nowhere else is an epsilon chosen (stability.md F3–F6).
#pragma once

#include <algorithm>
#include <limits>
#include <utility>

#include "raytrace/hit.hpp"
#include "raytrace/interval.hpp"
#include "raytrace/ray.hpp"

namespace rt {

enum class OffsetPolicy {
  // Move the re-projected hit point along the normal, to the side the ray leaves by, by kRayEpsilon
  // relative to the point's magnitude (Mitsuba 3 `offset_p`; stability.md F4a). Zero re-hits at any scale.
  Relative,
  // The course's P + 0.001·d (csc473-course.md §c.8), which its p3/p4 printrays outputs encode. Fails at
  // large coordinates and grazing angles (stability.md F4, F5); only for matching those digits.
  Course,
};

template <class T> constexpr T kRayEpsilon = T(16) * std::numeric_limits<T>::epsilon();
constexpr double kCourseEpsilon = 0.001;
// Shadow segments stop this fraction short of the light, so a light on a surface does not shadow itself.
template <class T> constexpr T kShadowEpsilon = T(64) * std::numeric_limits<T>::epsilon();

// The origin of a ray leaving `hit` in direction `dir`.
template <class T> Vec3<T> spawnOrigin(const Hit<T>& hit, const Vec3<T>& dir, OffsetPolicy policy) {
  if (policy == OffsetPolicy::Course) return hit.point + T(kCourseEpsilon) * dir;
  const T offset = kRayEpsilon<T> * std::max(T(1), maxAbs(hit.point));
  return hit.point + (glm::dot(hit.normal, dir) > T(0) ? offset : -offset) * hit.normal;
}

template <class T> Ray<T> spawnRay(const Hit<T>& hit, const Vec3<T>& dir, OffsetPolicy policy) {
  return Ray<T>{spawnOrigin(hit, dir, policy), dir};
}

// A ray from `hit` toward `target` with the interval that ends just before it: the shadow segment.
template <class T>
std::pair<Ray<T>, Interval<T>> spawnRayTo(const Hit<T>& hit, const Vec3<T>& target, OffsetPolicy policy) {
  const Vec3<T> dir = glm::normalize(target - hit.point);
  const Ray<T> ray = spawnRay(hit, dir, policy);
  const T dist = glm::length(target - ray.origin);
  return {ray, Interval<T>{T(0), dist * (T(1) - kShadowEpsilon<T>)}};
}

}  // namespace rt
