// What capped cylinders and cones share: a segment from base to cap, the ray split into its components along
// and across that axis, the disks that close the ends, and the choice of the nearest part that was hit.
#pragma once

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>

#include "raytrace/geometry/aabb.hpp"
#include "raytrace/geometry/hit.hpp"
#include "raytrace/geometry/interval.hpp"
#include "raytrace/geometry/ray.hpp"

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
  // Whether `point` lies strictly between the end planes, less than `radius(y)` from the axis at its height y.
  template <class Radius> bool inside(const Vec3<T>& point, const Radius& radius) const {
    const Vec3<T> p = point - base_;
    const T y = glm::dot(p, axis_);
    if (!(y > T(0) && y < height_)) return false;
    const T r = radius(y);
    return glm::dot(p, p) - y * y < r * r;
  }

  // The point at height y with the radial offset `across` (perpendicular to the axis).
  Vec3<T> at(T y, const Vec3<T>& across) const { return base_ + y * axis_ + across; }

  // Hits are re-projected this far inside the rim of a shape reaching `radius` from the axis: rounding the
  // world point (≈ ε·|p| per coordinate) must not put a side hit beyond an end or an end hit beyond the
  // side, where the offset along its own normal would not bring a spawned ray back inside (docs/reference/stability.md
  // F6: measured 6 of 30000 rays entering a float cylinder at |p| = 1e4 found the cap again without it).
  T rimMargin(T radius) const {
    return T(8) * std::numeric_limits<T>::epsilon() * std::max(T(1), maxAbs(base_) + height_ + radius);
  }

  // The height of a side hit, clamped to the ends less the rim margin: the re-projected point must not leave
  // the side (F4).
  T heightAt(const Split& s, T t, T radius) const {
    const T m = std::min(rimMargin(radius), height_ / T(2));
    return glm::clamp(s.oy + t * s.dy, m, height_ - m);
  }

  Split split(const Ray<T>& ray) const {
    const Vec3<T> o = ray.origin - base_;
    const T oy = glm::dot(o, axis_), dy = glm::dot(ray.dir, axis_);
    return {oy, dy, o - oy * axis_, ray.dir - dy * axis_};
  }

  // Whether the side surface's root t lies between the end planes; inclusive, so the rim has no crack
  // (docs/reference/stability.md F6).
  bool withinHeight(const Split& s, T t) const {
    const T y = s.oy + t * s.dy;
    return T(0) <= y && y <= height_;
  }

  // Where the ray crosses the end disk (Base or Cap) of radius `radius`. Computed only when the ray is not
  // parallel to the disk, where t would be ±∞ or NaN (docs/reference/stability.md F8); the radius bound is inclusive
  // (F6).
  std::optional<T> diskT(const Split& s, Part end, T radius) const {
    if (s.dy == T(0) || radius == T(0)) return std::nullopt;
    const T t = ((end == Part::Cap ? height_ : T(0)) - s.oy) / s.dy;
    const Vec3<T> across = s.op + t * s.dp;
    if (glm::dot(across, across) > radius * radius) return std::nullopt;
    return t;
  }

  // The hit on an end disk of radius `radius`: the point put exactly in the disk's plane and within the rim
  // margin of its edge, the normal along the axis, outward.
  Hit<T> diskHit(const Split& s, Part end, T t, T radius) const {
    Hit<T> hit;
    hit.t = t;
    const T y = end == Part::Cap ? height_ : T(0);
    Vec3<T> across = s.op + t * s.dp;
    const T inner = radius - std::min(rimMargin(radius), radius / T(2)), len = glm::length(across);
    if (len > inner) across *= inner / len;
    hit.point = at(y, across);
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
