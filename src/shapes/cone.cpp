#include "raytrace/shapes/cone.hpp"

#include <cmath>

namespace rt {

// The side is |op + t·dp| = r1 + k·(oy + t·dy) for heights y in [0, h] (Haines, "Essential ray tracing
// algorithms", in Glassner, An Introduction to Ray Tracing, 1989). Squared, it is a·t² + 2b·t + c = 0 with
//   a = dp·dp − (k·dy)²,  b = op·dp − R0·k·dy,  c = op·op − R0²,  R0 = r1 + k·oy,
// solved by the q-form (Numerical Recipes §5.6). Squaring adds the mirror cone beyond the apex; the apex lies
// outside (0, h) or on an end, so the height test removes it. a = 0 (ray parallel to a generator line) leaves
// the single root c/q = −c/2b; dy = 0 skips the disks (docs/reference/stability.md F8). Near the apex R0 → 0 and both b² and
// a·c are tiny differences of nearly equal terms, which float loses (t off by 2e-3 at t ≈ 7, docs/accuracy.md):
// the coefficients are formed in double, where the products of float inputs are exact and the cancellation
// leaves 29 more bits.
template <class T>
std::optional<Hit<T>> Cone<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  using Part = typename Axial<T>::Part;
  const auto s = frame_.split(ray);
  Nearest<T> nearest{range, std::nullopt};
  const glm::dvec3 op(s.op), dp(s.dp);
  const double r0 = double(baseRadius_) + double(slope_) * double(s.oy);
  const double kdy = double(slope_) * double(s.dy);
  const double a = glm::dot(dp, dp) - kdy * kdy;
  const double b = glm::dot(op, dp) - r0 * kdy;
  const double c = glm::dot(op, op) - r0 * r0;
  const double disc = b * b - a * c;
  if (disc >= 0) {
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    if (a != 0 && frame_.withinHeight(s, T(q / a))) nearest.consider(T(q / a), Part::Side);
    if (q != 0 && frame_.withinHeight(s, T(c / q))) nearest.consider(T(c / q), Part::Side);
  }
  if (!open_) {
    if (const auto t = frame_.diskT(s, Part::Base, baseRadius_)) nearest.consider(*t, Part::Base);
    if (const auto t = frame_.diskT(s, Part::Cap, capRadius_)) nearest.consider(*t, Part::Cap);
  }
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
    // Re-projected onto the side (docs/reference/stability.md F4): at the radius of its height, between the ends.
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
