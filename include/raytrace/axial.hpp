// What capped cylinders and cones share: a segment from base to cap, the ray split into its components along
// and across that axis, the disks that close the ends, and the choice of the nearest part that was hit.
#pragma once

#include <optional>

#include "raytrace/aabb.hpp"
#include "raytrace/hit.hpp"
#include "raytrace/interval.hpp"
#include "raytrace/ray.hpp"

namespace rt {

template <class T> class Axial {
 public:
  // A ray in the axis frame: height y = oy + t·dy above the base, radial vector op + t·dp across the axis.
  struct Split {
    T oy, dy;
    Vec3<T> op, dp;
  };
  enum class Part { Side, Base, Cap };

  Axial(const Vec3<T>& base, const Vec3<T>& cap)
      : base_(base), axis_(glm::normalize(cap - base)), height_(glm::length(cap - base)) {}

  const Vec3<T>& base() const { return base_; }
  const Vec3<T>& axis() const { return axis_; }
  T height() const { return height_; }

  Split split(const Ray<T>& ray) const {
    const Vec3<T> o = ray.origin - base_;
    const T oy = glm::dot(o, axis_), dy = glm::dot(ray.dir, axis_);
    return {oy, dy, o - oy * axis_, ray.dir - dy * axis_};
  }

  // Whether the side surface's root t lies between the end planes; inclusive, so the rim has no crack
  // (stability.md F6).
  bool withinHeight(const Split& s, T t) const {
    const T y = s.oy + t * s.dy;
    return T(0) <= y && y <= height_;
  }

  // Where the ray crosses the end disk (Base or Cap) of radius `radius`. Computed only when the ray is not
  // parallel to the disk, where t would be ±∞ or NaN (stability.md F8); the radius bound is inclusive (F6).
  std::optional<T> diskT(const Split& s, Part end, T radius) const {
    if (s.dy == T(0) || radius == T(0)) return std::nullopt;
    const T t = ((end == Part::Cap ? height_ : T(0)) - s.oy) / s.dy;
    const Vec3<T> across = s.op + t * s.dp;
    if (glm::dot(across, across) > radius * radius) return std::nullopt;
    return t;
  }

  // The hit on an end disk: the point put exactly in the disk's plane, the normal along the axis, outward.
  Hit<T> diskHit(const Split& s, Part end, T t) const {
    Hit<T> hit;
    hit.t = t;
    const T y = end == Part::Cap ? height_ : T(0);
    hit.point = base_ + y * axis_ + (s.op + t * s.dp);
    hit.normal = end == Part::Cap ? axis_ : -axis_;
    return hit;
  }

  // Grows `box` by the end disk of radius `radius`: across axis i a disk reaches radius·√(1 − axisᵢ²).
  void expandByDisk(Aabb<T>& box, Part end, T radius) const {
    const Vec3<T> centre = base_ + (end == Part::Cap ? height_ : T(0)) * axis_;
    const Vec3<T> reach = radius * glm::sqrt(glm::max(Vec3<T>(0), Vec3<T>(1) - axis_ * axis_));
    box.expand(centre - reach);
    box.expand(centre + reach);
  }

 private:
  Vec3<T> base_;
  Vec3<T> axis_;  // unit, from base to cap
  T height_;
};

// The nearest candidate t strictly inside an interval, and which part it lies on. Comparing with `<` keeps
// NaN out and lets the first part listed win a tie.
template <class T> struct Nearest {
  Interval<T> range;
  std::optional<typename Axial<T>::Part> part;

  void consider(T t, typename Axial<T>::Part p) {
    if (range.surrounds(t)) {
      range.max = t;
      part = p;
    }
  }
  T t() const { return range.max; }
};

}  // namespace rt
