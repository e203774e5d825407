#pragma once

#include "raytrace/shapes/object.hpp"

namespace rt {

// The plane n·p = d with unit n. POV-Ray semantics: the file's normal is normalized and d is the distance
// from the origin along it.
template <class T> class Plane final : public Object<T> {
 public:
  Plane(const Vec3<T>& normal, T distance, const Material& material, int id)
      : Object<T>(material, id), normal_(normal), distance_(distance) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  void closerHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* best) const override;
  uint32_t occludes(const Ray<T>* rays, const Interval<T>* ranges, uint32_t open) const override;
  std::optional<Aabb<T>> bounds() const override { return std::nullopt; }
  const char* name() const override { return "Plane"; }

 private:
  // Where the ray meets the plane; ±∞ or NaN when it runs parallel to it, which no interval surrounds.
  T distanceAlong(const Ray<T>& ray) const {
    return (distance_ - glm::dot(normal_, ray.origin)) / glm::dot(normal_, ray.dir);
  }
  Hit<T> hitAt(const Ray<T>& ray, T t) const;

  Vec3<T> normal_;
  T distance_;
};

}  // namespace rt
