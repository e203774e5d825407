// Up to four spheres of a leaf laid out lane by lane, tested against one ray at once in SIMD (as TriangleGroup
// does for triangles, and as Embree tests its sphere primitives four at a time).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "raytrace/accel/lane_group.hpp"
#include "raytrace/geometry/interval.hpp"
#include "raytrace/geometry/ray.hpp"
#include "raytrace/shapes/sphere.hpp"

namespace rt {

// Aligned to a cache line: a group of floats (128 bytes) takes two lines.
template <class T> struct alignas(64) SphereGroup : LaneGroup<T> {
  using typename LaneGroup<T>::Lanes;
  using Mask = decltype(Lanes{} < Lanes{});  // integer lanes, all bits set where a comparison holds
  using LaneGroup<T>::kSize;

  Lanes center[3]{}, radius{};  // [axis]: lane k holds sphere k's centre and radius
  bool robust = false;          // the formula of every sphere of the group (Sphere::robust())

  // Lane `k` becomes the sphere s; the group's spheres must share their formula.
  void set(int k, const Sphere<T>& s, uint32_t index) {
    for (int axis = 0; axis < 3; ++axis) center[axis][k] = s.center()[axis];
    radius[k] = s.radius();
    robust = s.robust();
    this->hold(k, index, s.id());
  }

  // The lanes whose sphere has a root strictly inside `range`, as bit k for lane k, with the nearer such root
  // in t[k] (Sphere::nearestRoot); and those with either root inside it (Sphere::meets).
  uint32_t hits(const Ray<T>& ray, Interval<T> range, Lanes& t) const {
    Lanes t0, t1;
    Mask met;
    if (!roots(ray, t0, t1, met)) return 0;
    t = ((range.min < t0) & (t0 < range.max)) ? t0 : t1;
    met &= (range.min < t) & (t < range.max);
    return this->bits(met);
  }
  uint32_t meets(const Ray<T>& ray, Interval<T> range) const {
    Lanes t0, t1;
    Mask met;
    if (!roots(ray, t0, t1, met)) return 0;
    met &= ((range.min < t0) & (t0 < range.max)) | ((range.min < t1) & (t1 < range.max));
    return this->bits(met);
  }

 private:
  // (Vectors are passed by reference: a vector of doubles returned by value would not be in one register.)
  static void sqrtOf(Lanes& x) {
#if defined(__SSE2__)
    if constexpr (sizeof(T) == 4) {
      const __m128 r = _mm_sqrt_ps(reinterpret_cast<const __m128&>(x));
      x = reinterpret_cast<const Lanes&>(r);
      return;
    }
#endif
    for (int k = 0; k < kSize; ++k) x[k] = std::sqrt(x[k]);
  }

  // Both roots of every lane's quadratic, by the group's formula: each lane does textbookRoots' or
  // robustRoots' operations in their order (roots.hpp), so that its roots have their bits. The lanes where
  // that function returns false are clear in `real`. False, with the roots left unset, when no lane in use has
  // real roots: most groups a ray reaches it misses, and the divisions are the dearest steps.
  bool roots(const Ray<T>& ray, Lanes& t0, Lanes& t1, Mask& real) const {
    const Lanes f[3] = {ray.origin.x - center[0], ray.origin.y - center[1], ray.origin.z - center[2]};
    const Vec3<T>& d = ray.dir;
    const T a = glm::dot(d, d);
    const Lanes ff = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
    const Lanes fd = f[0] * d.x + f[1] * d.y + f[2] * d.z;
    if (!robust) {
      const Lanes b = T(2) * fd;
      const Lanes c = ff - radius * radius;
      const Lanes disc = b * b - T(4) * a * c;
      real = ~(disc < T(0));
      if (!this->bits(real)) return false;
      Lanes root = disc;
      sqrtOf(root);
      t0 = (-b - root) / (T(2) * a);
      t1 = (-b + root) / (T(2) * a);
      return true;
    }
    const Lanes ba = fd / a;
    const Lanes l[3] = {f[0] - ba * d.x, f[1] - ba * d.y, f[2] - ba * d.z};
    Lanes lLen = l[0] * l[0] + l[1] * l[1] + l[2] * l[2];
    sqrtOf(lLen);
    const Lanes rr = (radius - lLen) * (radius + lLen);
    real = ~(rr < T(0));
    if (!this->bits(real)) return false;
    // q = −(b + copysign(√(a·rr), b)): the sign bit of b on the magnitude of the root.
    using Int = std::conditional_t<sizeof(T) == 4, int32_t, int64_t>;
    const Int sign = Int(1) << (8 * sizeof(T) - 1);
    Mask magnitude, signOf;
    Lanes root = a * rr;
    sqrtOf(root);
    std::memcpy(&magnitude, &root, sizeof root);
    std::memcpy(&signOf, &fd, sizeof fd);
    const Mask signedBits = (magnitude & ~sign) | (signOf & sign);
    Lanes signedRoot;
    std::memcpy(&signedRoot, &signedBits, sizeof signedRoot);
    const Lanes q = -(fd + signedRoot);
    const Lanes near = q / a, far = (ff - radius * radius) / q;
    const Mask swap = near > far;
    t0 = swap ? far : near;
    t1 = swap ? near : far;
    real &= ~(q == T(0));
    return true;
  }
};

}  // namespace rt
