#include "raytrace/shapes/transformed.hpp"

namespace rt {

template <class T>
Transformed<T>::Transformed(std::unique_ptr<Object<T>> inner, const Mat4<T>& worldFromObject,
                            const Material& material, int id, bool course)
    : Object<T>(material, id),
      inner_(std::move(inner)),
      worldFromObject_(worldFromObject),
      objectFromWorld_(glm::inverse(worldFromObject)),
      worldFromObjectNormal_(glm::transpose(glm::mat<3, 3, T, glm::defaultp>(objectFromWorld_))),
      course_(course) {}

// The object-space direction is M⁻¹·d without renormalizing, so the object-space t is the world t
// (docs/reference/csc473.md §c.10); normals map by the inverse transpose. The course tier's normal is the one at the
// world point brought back, M⁻¹·(o + t·d), as the reference's Object::CalculateNormalTransformed has it.
template <class T>
std::optional<Hit<T>> Transformed<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const Ray<T> local{Vec3<T>(objectFromWorld_ * glm::vec<4, T, glm::defaultp>(ray.origin, T(1))),
                     Vec3<T>(objectFromWorld_ * glm::vec<4, T, glm::defaultp>(ray.dir, T(0)))};
  auto hit = inner_->intersect(local, range);
  if (!hit) return std::nullopt;
  if (course_) {
    hit->point = ray.at(hit->t);
    hit->normal = inner_->normalAt(Vec3<T>(objectFromWorld_ * glm::vec<4, T, glm::defaultp>(hit->point, T(1))), *hit);
  } else {
    hit->point = Vec3<T>(worldFromObject_ * glm::vec<4, T, glm::defaultp>(hit->point, T(1)));
  }
  hit->normal = glm::normalize(worldFromObjectNormal_ * hit->normal);
  return hit;  // the inner object's hit: a CSG child's material stays its own
}

// The world box around the eight transformed corners of the object-space box.
template <class T> std::optional<Aabb<T>> Transformed<T>::bounds() const {
  const auto inner = inner_->bounds();
  if (!inner) return std::nullopt;
  Aabb<T> box;
  for (int i = 0; i < 8; ++i) {
    const Vec3<T> corner((i & 1) ? inner->max.x : inner->min.x, (i & 2) ? inner->max.y : inner->min.y,
                         (i & 4) ? inner->max.z : inner->min.z);
    box.expand(Vec3<T>(worldFromObject_ * glm::vec<4, T, glm::defaultp>(corner, T(1))));
  }
  return box;
}

template class Transformed<float>;
template class Transformed<double>;

}  // namespace rt
