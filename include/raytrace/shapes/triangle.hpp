#pragma once

#include "raytrace/shapes/object.hpp"

namespace rt {

// The triangle a, b, c, seen from both sides. Its normal (b − a) × (c − a), normalized, is the "outward"
// one (docs/reference/csc473.md §c.11). A degenerate triangle (zero area) is never hit.
template <class T> class Triangle final : public Object<T> {
 public:
  Triangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Material& material, int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override;
  const char* name() const override { return "Triangle"; }

  // Möller & Trumbore (1997), "Fast, minimum storage ray-triangle intersection": solves
  // o + t·d = a + u·(b − a) + v·(c − a) by Cramer's rule, which is the course's method (§c.11) with the
  // determinants written as scalar triple products. True when the ray meets the triangle a, a + ab, a + ac
  // strictly inside `range`, edges included (u, v ≥ 0, u + v ≤ 1: two triangles sharing an edge leave no
  // crack). Every test is written so that a NaN fails it. The one test of intersect(), inline so that a
  // hierarchy testing triangles from arrays of its own (accel/) gets the same bits.
  static bool solve(const Vec3<T>& a, const Vec3<T>& ab, const Vec3<T>& ac, const Ray<T>& ray, Interval<T> range,
                    T& t, T& u, T& v) {
    const Vec3<T> p = glm::cross(ray.dir, ac);
    const T det = glm::dot(ab, p);
    if (det == T(0)) return false;  // the ray is parallel to the triangle's plane
    const Vec3<T> s = ray.origin - a;
    u = glm::dot(s, p) / det;
    if (!(u >= T(0) && u <= T(1))) return false;
    const Vec3<T> q = glm::cross(s, ab);
    v = glm::dot(ray.dir, q) / det;
    if (!(v >= T(0) && u + v <= T(1))) return false;
    t = glm::dot(ac, q) / det;
    return range.surrounds(t);
  }
  // The vertex a, the edges ab and ac, and whether the triangle has no area (then it is never hit).
  const Vec3<T>& a() const { return a_; }
  const Vec3<T>& ab() const { return ab_; }
  const Vec3<T>& ac() const { return ac_; }
  bool degenerate() const { return degenerate_; }

 private:
  Vec3<T> a_, ab_, ac_;  // a vertex and the two edges from it
  Vec3<T> normal_;
  bool degenerate_;
};

}  // namespace rt
