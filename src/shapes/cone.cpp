#include "raytrace/shapes/cone.hpp"

#include <cmath>

namespace rt {

// The side is |op + t·dp| = r1 + k·(oy + t·dy) for heights y in [0, h] (Haines, "Essential ray tracing
// algorithms", in Glassner, An Introduction to Ray Tracing, 1989). Squared, it is a·t² + 2b·t + c = 0 with
//   a = dp·dp − (k·dy)²,  b = op·dp − R0·k·dy,  c = op·op − R0²,  R0 = r1 + k·oy,
// solved by the q-form (Numerical Recipes §5.6). Squaring adds the mirror cone beyond the apex; the apex lies
// outside (0, h) or on an end, so the height test removes it. a = 0 (ray parallel to a generator line) leaves
// the single root c/q = −c/2b; dy = 0 skips the disks (stability.md F8).
template <class T>
std::optional<Hit<T>> Cone<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  using Part = typename Axial<T>::Part;
  const auto s = frame_.split(ray);
  Nearest<T> nearest{range, std::nullopt};
  const T r0 = baseRadius_ + slope_ * s.oy;
  const T kdy = slope_ * s.dy;
  const T a = glm::dot(s.dp, s.dp) - kdy * kdy;
  const T b = glm::dot(s.op, s.dp) - r0 * kdy;
  const T c = glm::dot(s.op, s.op) - r0 * r0;
  const T disc = b * b - a * c;
  if (disc >= T(0)) {
    const T q = -(b + std::copysign(std::sqrt(disc), b));
    if (a != T(0) && frame_.withinHeight(s, q / a)) nearest.consider(q / a, Part::Side);
    if (q != T(0) && frame_.withinHeight(s, c / q)) nearest.consider(c / q, Part::Side);
  }
  if (const auto t = frame_.diskT(s, Part::Base, baseRadius_)) nearest.consider(*t, Part::Base);
  if (const auto t = frame_.diskT(s, Part::Cap, capRadius_)) nearest.consider(*t, Part::Cap);
  if (!nearest.part) return std::nullopt;

  const T t = nearest.t();
  Hit<T> hit;
  if (*nearest.part == Part::Side) {
    hit.t = t;
    // The gradient of |radial| − (r1 + k·y) is u − k·axis, u the unit radial direction (0 at the apex).
    const Vec3<T> radial = s.op + t * s.dp;
    const T len = glm::length(radial);
    const Vec3<T> u = len > T(0) ? radial / len : Vec3<T>(0);
    hit.normal = glm::normalize(u - slope_ * frame_.axis());
    if (!hit.hasNormal()) return std::nullopt;
    // Re-projected onto the side (stability.md F4): at the radius of its height, between the ends.
    const T y = frame_.heightAt(s, t, std::max(baseRadius_, capRadius_));
    hit.point = frame_.at(y, (baseRadius_ + slope_ * y) * u);
  } else {
    hit = frame_.diskHit(s, *nearest.part, t, *nearest.part == Part::Cap ? capRadius_ : baseRadius_);
  }
  hit.object = this;
  return hit;
}

template class Cone<float>;
template class Cone<double>;

}  // namespace rt
