#include "raytrace/shapes/sphere.hpp"

#include <cmath>

namespace rt {

template <class T>
std::optional<Hit<T>> Sphere<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  T t;
  if (!nearestRoot(center_, radius_, robust_, ray, range, t)) return std::nullopt;
  return hitAt(center_, radius_, ray, t, this);
}

// Object::closerHits with Sphere's own intersect() named, so that it is inlined rather than called through
// the virtual table once per ray.
template <class T>
void Sphere<T>::closerHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* best) const {
  for (int i = 0; i < n; ++i) {
    if (auto hit = Sphere::intersect(rays[i], {range.min, best[i] ? best[i]->t : range.max})) best[i] = hit;
  }
}

// A shadow ray needs no hit record: only whether a root lies inside its segment.
template <class T>
uint32_t Sphere<T>::occludes(const Ray<T>* rays, const Interval<T>* ranges, uint32_t open) const {
  uint32_t occluded = 0;
  for (uint32_t mask = open; mask; mask &= mask - 1) {
    const int i = __builtin_ctz(mask);
    if (meets(center_, radius_, robust_, rays[i], ranges[i])) occluded |= 1u << i;
  }
  return occluded;
}

template <class T> Vec3<T> Sphere<T>::normalAt(const Vec3<T>& point, const Hit<T>&) const {
  return glm::normalize(point - center_);
}

template <class T> std::optional<Aabb<T>> Sphere<T>::bounds() const {
  return Aabb<T>{center_ - Vec3<T>(radius_), center_ + Vec3<T>(radius_)};
}

template class Sphere<float>;
template class Sphere<double>;

}  // namespace rt
