#pragma once

#include <algorithm>
#include <memory>
#include <ostream>
#include <string_view>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Triangle;

// What a file says of a triangle: `triangle { a, b, c }`.
struct TriangleDesc {
  glm::dvec3 a, b, c;

  static bool named(std::string_view word) { return word == "triangle"; }
  static const char* name() { return "Triangle"; }
  static constexpr bool kFloatErrorBound = true;

  template <class Reader> static TriangleDesc read(Reader& r, std::string_view) {
    TriangleDesc t;
    t.a = r.vec3("the first triangle vertex");
    r.comma("after the first triangle vertex");
    t.b = r.vec3("the second triangle vertex");
    r.comma("after the second triangle vertex");
    t.c = r.vec3("the third triangle vertex");
    return t;
  }
  double smallestFeature() const {
    return std::min({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
  }
  Ball boundingBall() const {
    const glm::dvec3 m = (a + b + c) / 3.0;
    return {m, std::max({glm::length(a - m), glm::length(b - m), glm::length(c - m)})};
  }
  FlatFaces flatFaces() const {
    FlatFaces f;
    f.face[0] = {a, b - a, c - a, true};
    f.count = 1;
    return f;
  }
  void describe(std::ostream& out) const {
    out << "- Vertices[0]: " << braces(a) << "\n- Vertices[1]: " << braces(b) << "\n- Vertices[2]: " << braces(c)
        << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& o) const {
    return std::make_unique<Triangle<T>>(Vec3<T>(a), Vec3<T>(b), Vec3<T>(c), o.material, o.id);
  }
};

// The triangle a, b, c, seen from both sides. Its normal (b − a) × (c − a), normalized, is the "outward"
// one (docs/reference/csc473.md §c.11). A degenerate triangle (zero area) is never hit.
template <class T> class Triangle final : public Object<T> {
 public:
  Triangle(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, const Material& material, int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override;
  bool inside(const Vec3<T>&) const override { return false; }
  const char* name() const override { return TriangleDesc::name(); }

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
