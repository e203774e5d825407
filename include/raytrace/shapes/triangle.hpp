#pragma once

#include "raytrace/shapes/object.hpp"

namespace rt {

// The triangle a, b, c, seen from both sides. Its normal (b − a) × (c − a), normalized, is the "outward"
// one (docs/reference/csc473.md §c.11). A degenerate triangle (zero area) is never hit.
template <class T> class Triangle final : public Object<T> {
 public:
  Triangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Material& material, int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override;
  const char* name() const override { return "Triangle"; }

 private:
  Vec3<T> a_, ab_, ac_;  // a vertex and the two edges from it
  Vec3<T> normal_;
  bool degenerate_;
};

}  // namespace rt
