#include "raytrace/shapes/disc.hpp"

#include <limits>

namespace rt {

// The plane's t = n·(c − o) / (n·d), as Plane's (a ray parallel to it never hits: ±∞ or NaN), then the hit's
// squared distance from the centre between hole² and radius².
template <class T> std::optional<Hit<T>> Disc<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const T t = glm::dot(normal_, center_ - ray.origin) / glm::dot(normal_, ray.dir);
  if (!range.surrounds(t)) return std::nullopt;
  const Vec3<T> p = ray.at(t);
  const Vec3<T> onPlane = p - normal_ * glm::dot(normal_, p - center_);  // re-projected onto the plane
  const T r2 = glm::dot(onPlane - center_, onPlane - center_);
  if (r2 > radius_ * radius_ || r2 < hole_ * hole_) return std::nullopt;
  Hit<T> hit;
  hit.t = t;
  hit.point = onPlane;
  hit.normal = normal_;
  hit.object = this;
  return hit;
}

// A circle of radius r across unit n reaches r·√(1 − nᵢ²) from its centre along axis i; widened by a few
// roundings so that the rim's hits stay inside.
template <class T> std::optional<Aabb<T>> Disc<T>::bounds() const {
  const Vec3<T> reach = radius_ * glm::sqrt(glm::max(Vec3<T>(0), Vec3<T>(1) - normal_ * normal_)) +
                        radius_ * T(8) * std::numeric_limits<T>::epsilon();
  return Aabb<T>{center_ - reach, center_ + reach};
}

template class Disc<float>;
template class Disc<double>;

}  // namespace rt
