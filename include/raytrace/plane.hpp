#pragma once

#include "raytrace/object.hpp"

namespace rt {

// The plane n·p = d with unit n. POV-Ray semantics: the file's normal is normalized and d is the distance
// from the origin along it.
template <class T> class Plane final : public Object<T> {
 public:
  Plane(const Vec3<T>& normal, T distance, const Material& material, int id)
      : Object<T>(material, id), normal_(normal), distance_(distance) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return std::nullopt; }

 private:
  Vec3<T> normal_;
  T distance_;
};

}  // namespace rt
