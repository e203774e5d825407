#pragma once

#include "raytrace/shapes/axial.hpp"
#include "raytrace/shapes/object.hpp"

namespace rt {

// POV-Ray's `cone { base, r1, cap, r2 }`: a truncated cone whose radius goes linearly from r1 at the base to r2
// at the cap, closed by disks at both ends (a radius of 0 is a point, with no disk).
template <class T> class Cone final : public Object<T> {
 public:
  Cone(const Vec3<T>& base, T baseRadius, const Vec3<T>& cap, T capRadius, const Material& material, int id)
      : Object<T>(material, id),
        frame_(base, cap),
        baseRadius_(baseRadius),
        capRadius_(capRadius),
        slope_((capRadius - baseRadius) / frame_.height()) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return frame_.bounds(baseRadius_, capRadius_); }
  const char* name() const override { return "Cone"; }

 private:
  Axial<T> frame_;
  T baseRadius_, capRadius_;
  T slope_;  // k: the radius at height y is r1 + k·y
};

}  // namespace rt
