// POV-Ray's `clipped_by`: only the parts of an object's surface inside every clipping object remain, and no
// new surface closes the cut (POV-Ray 3.7 manual §3.4.5.5, "Clipped_By"), unlike an intersection.
#pragma once

#include <memory>
#include <vector>

#include "raytrace/shapes/object.hpp"

namespace rt {

template <class T> class Clipped final : public Object<T> {
 public:
  Clipped(std::unique_ptr<Object<T>> inner, std::vector<std::unique_ptr<Object<T>>> clips, const Material& material,
          int id);

  // The inner object's first crossing inside all the clipping objects.
  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  // Inside every clip and the object; the clips stay when a difference takes the complement, as POV-Ray's
  // pictures of a difference with a clipped child show (docs/shapes.md, "clipped_by").
  bool inside(const Vec3<T>& p) const override { return insideClips(p) && inner_->inside(p); }
  bool insideComplement(const Vec3<T>& p) const override { return insideClips(p) && !inner_->inside(p); }
  std::optional<Aabb<T>> bounds() const override;
  const char* name() const override { return inner_->name(); }
  void forEachMaterial(const std::function<void(const Material&)>& f) const override { inner_->forEachMaterial(f); }

 private:
  bool insideClips(const Vec3<T>& p) const;

  std::unique_ptr<Object<T>> inner_;
  std::vector<std::unique_ptr<Object<T>>> clips_;
};

}  // namespace rt
