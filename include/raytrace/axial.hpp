// What capped cylinders and cones share: a segment from base to cap, the ray split into its components along
// and across that axis, the disks that close the ends, and the choice of the nearest part that was hit.
#pragma once

#include <optional>
#include <utility>

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

  const Vec3<T>& axis() const { return axis_; }
  T height() const { return height_; }

  // The point at height y with the radial offset `across` (perpendicular to the axis).
  Vec3<T> at(T y, const Vec3<T>& across) const { return base_ + y * axis_ + across; }

  // The height of a side hit, clamped to the ends: the re-projected point must not leave the side (F4).
  T heightAt(const Split& s, T t) const { return glm::clamp(s.oy + t * s.dy, T(0), height_); }

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
    hit.point = at(y, s.op + t * s.dp);
    hit.normal = end == Part::Cap ? axis_ : -axis_;
    return hit;
  }

  // The exact bounds of the two end disks, hence of the whole shape: across axis i a disk of radius ρ reaches
  // ρ·√(1 − axisᵢ²) from its centre.
  Aabb<T> bounds(T baseRadius, T capRadius) const {
    const Vec3<T> across = glm::sqrt(glm::max(Vec3<T>(0), Vec3<T>(1) - axis_ * axis_));
    Aabb<T> box;
    for (const auto& [y, radius] : {std::pair<T, T>{T(0), baseRadius}, {height_, capRadius}}) {
      box.expand(at(y, -radius * across));
      box.expand(at(y, radius * across));
    }
    return box;
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
