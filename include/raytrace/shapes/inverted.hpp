// POV-Ray's `inverse`: the same surface with inside and outside swapped (POV-Ray 3.7 manual §3.4.5.5,
// "Inverse"), so a CSG child marked inverse stands for its complement.
#pragma once

#include <memory>

#include "raytrace/shapes/object.hpp"

namespace rt {

template <class T> class Inverted final : public Object<T> {
 public:
  Inverted(std::unique_ptr<Object<T>> inner, const Material& material, int id)
      : Object<T>(material, id), inner_(std::move(inner)) {}

  // The inner hit with its normal turned to point out of the new inside.
  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override {
    auto hit = inner_->intersect(ray, range);
    if (hit) hit->normal = -hit->normal;
    return hit;
  }
  uint32_t occludes(const Ray<T>* rays, const Interval<T>* ranges, uint32_t open) const override {
    return inner_->occludes(rays, ranges, open);
  }
  bool inside(const Vec3<T>& p) const override { return !inner_->inside(p); }
  // The solid is unbounded, which an intersection or a clip that holds it relies on (Csg::bounds).
  std::optional<Aabb<T>> bounds() const override { return std::nullopt; }
  const char* name() const override { return inner_->name(); }
  void forEachMaterial(const std::function<void(const Material&)>& f) const override { inner_->forEachMaterial(f); }

 private:
  std::unique_ptr<Object<T>> inner_;
};

}  // namespace rt
