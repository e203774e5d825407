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

template <class T>
std::optional<Hit<T>> Triangle<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  T t, u, v;
  if (degenerate_ || !solve(a_, ab_, ac_, ray, range, t, u, v)) return std::nullopt;
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
