// The quadratics of the round shapes (sphere, cylinder side): the roots of |f + t·d|² = r²; and the choice
// of formula a sphere uses.
#pragma once

#include <cmath>
#include <utility>

#include "raytrace/geometry/math.hpp"

namespace rt {

// How a sphere solves its quadratic: the textbook formula (cheaper, exact enough for a small precision budget)
// or robustRoots() below; Auto asks chooseArithmetic() to choose per scene.
enum class SphereMethod { Auto, Textbook, Robust };

// The textbook quadratic (lecture 3; Shirley, Fundamentals of Computer Graphics §4.4.1): a·t² + b·t + c = 0 with
// b = 2 d·f, Δ = b² − 4ac. Its error grows as ε·R² (docs/reference/stability.md F1), so chooseArithmetic() uses
// it only where R is small. Forced inline as robustRoots() is.
template <class T>
[[gnu::always_inline]] inline bool textbookRoots(const Vec3<T>& f, const Vec3<T>& d, T radius, T& t0, T& t1) {
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

// Ray-sphere with the two robust steps of Ray Tracing Gems ch. 7 (Haines et al. 2019), also used by pbrt-v4:
//  - the discriminant from the perpendicular distance l of the centre to the ray, r² − |l|², which loses
//    only ≈ε·D instead of ε·D²/r to cancellation (docs/reference/stability.md F1);
//  - the root pair q = −(b + sign(b)·√Δ), t0 = q/a, t1 = c/q, which avoids subtracting nearly equal numbers
//    (Numerical Recipes §5.6; docs/reference/stability.md F2).
// With f = o − c the quadratic is a·t² + 2b·t + c = 0, a = d·d, b = f·d, c = f·f − r², Δ = b² − a·c.
// The same equation in the plane perpendicular to an axis is the ray-cylinder side test. Needs d ≠ 0.
// Forced inline: it is the inner loop of every sphere test, and GCC left it a call
// (docs/performance-notes.md, "Whitted path").
template <class T>
[[gnu::always_inline]] inline bool robustRoots(const Vec3<T>& f, const Vec3<T>& d, T radius, T& t0, T& t1) {
  const T a = glm::dot(d, d);
  const T b = glm::dot(f, d);
  const Vec3<T> l = f - (b / a) * d;
  const T lLen = glm::length(l);
  const T rr = (radius - lLen) * (radius + lLen);  // Δ/a, factored against cancellation
  if (rr < T(0)) return false;
  const T q = -(b + std::copysign(std::sqrt(a * rr), b));
  if (q == T(0)) return false;  // origin on the surface, ray tangent there: no root away from it
  t0 = q / a;
  t1 = (glm::dot(f, f) - radius * radius) / q;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

}  // namespace rt
