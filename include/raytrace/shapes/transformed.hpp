// An object placed in the world by a matrix: the ray is taken into object space, the hit brought back.
#pragma once

#include <memory>

#include "raytrace/shapes/object.hpp"

namespace rt {

template <class T> class Transformed final : public Object<T> {
 public:
  // `course`: the course tier's hit (scene/arithmetic.hpp), the world point o + t·d with the normal the inner
  // shape has at M⁻¹ of it, instead of the inner shape's hit point and normal carried to the world.
  Transformed(std::unique_ptr<Object<T>> inner, const Mat4<T>& worldFromObject, const Material& material,
              int id, bool course = false);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override;
  bool inside(const Vec3<T>& p) const override {
    return inner_->inside(Vec3<T>(objectFromWorld_ * glm::vec<4, T, glm::defaultp>(p, T(1))));
  }
  const char* name() const override { return inner_->name(); }
  void forEachMaterial(const std::function<void(const Material&)>& f) const override { inner_->forEachMaterial(f); }

 private:
  std::unique_ptr<Object<T>> inner_;
  Mat4<T> worldFromObject_;
  Mat4<T> objectFromWorld_;
  glm::mat<3, 3, T, glm::defaultp> worldFromObjectNormal_;  // (M⁻¹)ᵀ, for normals
  bool course_;
};

}  // namespace rt
