#pragma once

#include "raytrace/geometry/roots.hpp"
#include "raytrace/shapes/object.hpp"

namespace rt {

template <class T> class Sphere final : public Object<T> {
 public:
  Sphere(const Vec3<T>& center, T radius, SphereMethod method, const Material& material, int id)
      : Object<T>(material, id), center_(center), radius_(radius), robust_(method != SphereMethod::Textbook) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  uint32_t occludes(const Ray<T>* rays, const Interval<T>* ranges, uint32_t open) const override;
  Vec3<T> normalAt(const Vec3<T>& point, const Hit<T>& hit) const override;
  std::optional<Aabb<T>> bounds() const override;
  const char* name() const override { return "Sphere"; }

 private:
  // The roots of the ray's quadratic, by the method chosen for the scene.
  bool roots(const Ray<T>& ray, T& t0, T& t1) const;

  Vec3<T> center_;
  T radius_;
  bool robust_;  // see chooseArithmetic(): the textbook formula is cheaper and exact enough for small R
};

}  // namespace rt
