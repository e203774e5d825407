#include "raytrace/shapes/sphere.hpp"

#include <cmath>

#include "raytrace/geometry/roots.hpp"

namespace rt {

// The textbook quadratic (lecture 3; Shirley, Fundamentals of Computer Graphics §4.4.1): a·t² + b·t + c = 0 with
// b = 2 d·f, Δ = b² − 4ac. Its error grows as ε·R² (docs/reference/stability.md F1), so chooseArithmetic() uses it only
// where R is small.
template <class T> bool textbookRoots(const Vec3<T>& f, const Vec3<T>& d, T radius, T& t0, T& t1) {
  const T a = glm::dot(d, d);
  const T b = T(2) * glm::dot(d, f);
  const T c = glm::dot(f, f) - radius * radius;
  const T disc = b * b - T(4) * a * c;
  if (disc < T(0)) return false;
  const T root = std::sqrt(disc);
  t0 = (-b - root) / (T(2) * a);
  t1 = (-b + root) / (T(2) * a);
  return true;
}

template <class T> bool Sphere<T>::roots(const Ray<T>& ray, T& t0, T& t1) const {
  const Vec3<T> f = ray.origin - center_;
  return robust_ ? robustRoots(f, ray.dir, radius_, t0, t1) : textbookRoots(f, ray.dir, radius_, t0, t1);
}

template <class T>
std::optional<Hit<T>> Sphere<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  T t0, t1;
  if (!roots(ray, t0, t1)) return std::nullopt;
  T t = t0;
  if (!range.surrounds(t)) {
    t = t1;
    if (!range.surrounds(t)) return std::nullopt;
  }
  Hit<T> hit;
  hit.t = t;
  hit.normal = glm::normalize(ray.at(t) - center_);
  hit.point = center_ + radius_ * hit.normal;  // re-projected onto the surface (docs/reference/stability.md F4)
  hit.object = this;
  return hit;
}

// A shadow ray needs no hit record: only whether a root lies inside its segment.
template <class T>
uint32_t Sphere<T>::occludes(const Ray<T>* rays, const Interval<T>* ranges, uint32_t open) const {
  uint32_t occluded = 0;
  for (uint32_t mask = open; mask; mask &= mask - 1) {
    const int i = __builtin_ctz(mask);
    T t0, t1;
    if (roots(rays[i], t0, t1) && (ranges[i].surrounds(t0) || ranges[i].surrounds(t1))) occluded |= 1u << i;
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
