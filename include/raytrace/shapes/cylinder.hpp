#pragma once

#include "raytrace/shapes/axial.hpp"
#include "raytrace/shapes/object.hpp"

namespace rt {

// A cylinder of radius r around the segment base→cap, closed at both ends by disks (POV-Ray's `cylinder`
// without `open`). The .cli language's vertical `cylinder r x z ymin ymax` is the same shape.
template <class T> class Cylinder final : public Object<T> {
 public:
  Cylinder(const Vec3<T>& base, const Vec3<T>& cap, T radius, const Material& material, int id)
      : Object<T>(material, id), frame_(base, cap), radius_(radius) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return frame_.bounds(radius_, radius_); }
  const char* name() const override { return "Cylinder"; }

 private:
  Axial<T> frame_;
  T radius_;
};

}  // namespace rt
