#include "raytrace/plane.hpp"

namespace rt {

// t = (d − n·o) / (n·d). A ray parallel to the plane (n·d = 0) never hits it, even when it lies in the plane:
// that would give t = ±∞ or NaN (stability.md F7).
template <class T>
std::optional<Hit<T>> Plane<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const T denom = glm::dot(normal_, ray.dir);
  if (denom == T(0)) return std::nullopt;
  const T t = (distance_ - glm::dot(normal_, ray.origin)) / denom;
  if (!range.surrounds(t)) return std::nullopt;
  Hit<T> hit;
  hit.t = t;
  const Vec3<T> p = ray.at(t);
  hit.point = p - normal_ * (glm::dot(normal_, p) - distance_);  // re-projected onto the plane
  hit.normal = normal_;
  hit.object = this;
  return hit;
}

template class Plane<float>;
template class Plane<double>;

}  // namespace rt
