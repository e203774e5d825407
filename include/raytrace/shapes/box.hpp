#pragma once

#include "raytrace/shapes/object.hpp"

namespace rt {

// An axis-aligned box. POV-Ray and the course accept the two corners in any order; they are sorted here.
template <class T> class Box final : public Object<T> {
 public:
  Box(const Vec3<T>& corner0, const Vec3<T>& corner1, const Material& material, int id)
      : Object<T>(material, id), min_(glm::min(corner0, corner1)), max_(glm::max(corner0, corner1)) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return Aabb<T>{min_, max_}; }
  const char* name() const override { return "Box"; }

 private:
  Vec3<T> min_, max_;
};

}  // namespace rt
