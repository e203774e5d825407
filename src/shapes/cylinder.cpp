#include "raytrace/shapes/cylinder.hpp"

#include "raytrace/geometry/roots.hpp"

namespace rt {

// The side is the circle |op + t·dp| = r in the plane across the axis, solved with the sphere's robust
// quadratic; the ends are disks. A ray parallel to the axis (dp = 0) meets only the ends; one across the axis
// (dy = 0) meets only the side (docs/reference/stability.md F8).
template <class T>
std::optional<Hit<T>> Cylinder<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  using Part = typename Axial<T>::Part;
  const auto s = frame_.split(ray);
  Nearest<T> nearest{range, std::nullopt};
  T t0, t1;
  if (glm::dot(s.dp, s.dp) > T(0) && robustRoots(s.op, s.dp, radius_, t0, t1)) {
    if (frame_.withinHeight(s, t0)) nearest.consider(t0, Part::Side);
    if (frame_.withinHeight(s, t1)) nearest.consider(t1, Part::Side);
  }
  if (!open_) {
    if (const auto t = frame_.diskT(s, Part::Base, radius_)) nearest.consider(*t, Part::Base);
    if (const auto t = frame_.diskT(s, Part::Cap, radius_)) nearest.consider(*t, Part::Cap);
  }
  if (!nearest.part) return std::nullopt;

  const T t = nearest.t();
  Hit<T> hit;
  if (*nearest.part == Part::Side) {
    hit.t = t;
    hit.normal = glm::normalize(s.op + t * s.dp);
    if (!hit.hasNormal()) return std::nullopt;
    // Re-projected onto the side (docs/reference/stability.md F4): at the radius, between the ends.
    hit.point = frame_.at(frame_.heightAt(s, t, radius_), radius_ * hit.normal);
  } else {
    hit = frame_.diskHit(s, *nearest.part, t, radius_);
  }
  hit.object = this;
  return hit;
}

template class Cylinder<float>;
template class Cylinder<double>;

}  // namespace rt
