#include "raytrace/shapes/plane.hpp"

namespace rt {

// t = (d − n·o) / (n·d). A ray parallel to the plane (n·d = 0) never hits it, even when it lies in the plane:
// t = ±∞ or NaN, which no open interval surrounds (docs/reference/stability.md F7).
template <class T>
std::optional<Hit<T>> Plane<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const T t = distanceAlong(ray);
  if (!range.surrounds(t)) return std::nullopt;
  return hitAt(ray, t);
}

template <class T>
void Plane<T>::closerHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* best) const {
  for (int i = 0; i < n; ++i) {
    const T t = distanceAlong(rays[i]);
    if (Interval<T>{range.min, best[i] ? best[i]->t : range.max}.surrounds(t)) best[i] = hitAt(rays[i], t);
  }
}

template <class T> uint32_t Plane<T>::occludes(const Ray<T>* rays, const Interval<T>* ranges, uint32_t open) const {
  uint32_t occluded = 0;
  for (uint32_t mask = open; mask; mask &= mask - 1) {
    const int i = __builtin_ctz(mask);
    occluded |= uint32_t(ranges[i].surrounds(distanceAlong(rays[i]))) << i;
  }
  return occluded;
}

template <class T> Hit<T> Plane<T>::hitAt(const Ray<T>& ray, T t) const {
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
