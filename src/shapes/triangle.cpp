#include "raytrace/shapes/triangle.hpp"

#include <limits>

namespace rt {

template <class T>
Triangle<T>::Triangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Material& material, int id)
    : Object<T>(material, id), a_(a), ab_(b - a), ac_(c - a) {
  const Vec3<T> n = glm::cross(ab_, ac_);
  const T twiceArea = glm::length(n);
  // Collinear vertices (or a length that overflowed) define no plane: such a triangle is never hit.
  degenerate_ = !(twiceArea > T(0) && twiceArea < std::numeric_limits<T>::infinity());
  normal_ = degenerate_ ? Vec3<T>(0) : n / twiceArea;
}

// Möller & Trumbore (1997), "Fast, minimum storage ray-triangle intersection": solve
// o + t·d = a + u·(b − a) + v·(c − a) by Cramer's rule, which is the course's method (§c.11) with the
// determinants written as scalar triple products. Edges count as inside (u, v ≥ 0, u + v ≤ 1), so two
// triangles sharing an edge leave no crack. Every test is written so that a NaN fails it.
template <class T>
std::optional<Hit<T>> Triangle<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  if (degenerate_) return std::nullopt;
  const Vec3<T> p = glm::cross(ray.dir, ac_);
  const T det = glm::dot(ab_, p);
  if (det == T(0)) return std::nullopt;  // the ray is parallel to the triangle's plane
  const Vec3<T> s = ray.origin - a_;
  const T u = glm::dot(s, p) / det;
  if (!(u >= T(0) && u <= T(1))) return std::nullopt;
  const Vec3<T> q = glm::cross(s, ab_);
  const T v = glm::dot(ray.dir, q) / det;
  if (!(v >= T(0) && u + v <= T(1))) return std::nullopt;
  const T t = glm::dot(ac_, q) / det;
  if (!range.surrounds(t)) return std::nullopt;
  Hit<T> hit;
  hit.t = t;
  hit.point = a_ + u * ab_ + v * ac_;  // on the triangle's plane by construction (docs/reference/stability.md F4)
  hit.normal = normal_;
  hit.object = this;
  return hit;
}

template <class T> std::optional<Aabb<T>> Triangle<T>::bounds() const {
  Aabb<T> box;
  box.expand(a_);
  box.expand(a_ + ab_);
  box.expand(a_ + ac_);
  return box;
}

template class Triangle<float>;
template class Triangle<double>;

}  // namespace rt
