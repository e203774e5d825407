#pragma once

#include <memory>
#include <ostream>
#include <string_view>

#include "raytrace/geometry/roots.hpp"
#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Sphere;

// What a file says of a sphere: `sphere { center, radius }`.
struct SphereDesc {
  glm::dvec3 center;
  double radius;

  static bool named(std::string_view word) { return word == "sphere"; }
  static const char* name() { return "Sphere"; }
  static constexpr bool kFloatErrorBound = true;

  template <class Reader> static SphereDesc read(Reader& r, std::string_view) {
    const glm::dvec3 center = r.vec3("the sphere center");
    r.comma("after the sphere center");
    return {center, r.positive("the sphere radius")};
  }
  double smallestFeature() const { return radius; }
  Ball boundingBall() const { return {center, radius}; }
  FlatFaces flatFaces() const { return {}; }  // curved: its own checks (scene/tier_domain)
  void describe(std::ostream& out) const {
    out << "- Center: " << braces(center) << "\n- Radius: " << fixed4(radius) << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Sphere<T>>(Vec3<T>(center), T(radius), b.sphere, b.material, b.id);
  }
};

template <class T> class Sphere final : public Object<T> {
 public:
  Sphere(const Vec3<T>& center, T radius, SphereMethod method, const Material& material, int id)
      : Object<T>(material, id), center_(center), radius_(radius), robust_(method != SphereMethod::Textbook) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  void closerHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* best) const override;
  uint32_t occludes(const Ray<T>* rays, const Interval<T>* ranges, uint32_t open) const override;
  Vec3<T> normalAt(const Vec3<T>& point, const Hit<T>& hit) const override;
  std::optional<Aabb<T>> bounds() const override;
  bool inside(const Vec3<T>& p) const override { return glm::dot(p - center_, p - center_) < radius_ * radius_; }
  const char* name() const override { return SphereDesc::name(); }

  // The tests of intersect() and occludes() on the sphere (center, radius) by the method chosen for the scene,
  // inline so that a hierarchy testing spheres from arrays of its own (accel/) gets the same bits. nearestRoot:
  // the nearer root strictly inside `range`, if any; meets: whether either root lies strictly inside it.
  static bool roots(const Vec3<T>& center, T radius, bool robust, const Ray<T>& ray, T& t0, T& t1) {
    const Vec3<T> f = ray.origin - center;
    return robust ? robustRoots(f, ray.dir, radius, t0, t1) : textbookRoots(f, ray.dir, radius, t0, t1);
  }
  static bool nearestRoot(const Vec3<T>& center, T radius, bool robust, const Ray<T>& ray, Interval<T> range,
                          T& t) {
    T t0, t1;
    if (!roots(center, radius, robust, ray, t0, t1)) return false;
    t = range.surrounds(t0) ? t0 : t1;
    return range.surrounds(t);
  }
  static bool meets(const Vec3<T>& center, T radius, bool robust, const Ray<T>& ray, Interval<T> range) {
    T t0, t1;
    return roots(center, radius, robust, ray, t0, t1) && (range.surrounds(t0) || range.surrounds(t1));
  }
  // intersect()'s record of the hit at t, a root nearestRoot() gave on this ray; nullopt where the sphere is
  // too small for a normal. A hierarchy that found t in its own arrays makes the record without a second test.
  static std::optional<Hit<T>> hitAt(const Vec3<T>& center, T radius, const Ray<T>& ray, T t,
                                     const Object<T>* object) {
    Hit<T> hit;
    hit.t = t;
    hit.normal = glm::normalize(ray.at(t) - center);
    if (!hit.hasNormal()) return std::nullopt;
    hit.point = center + radius * hit.normal;  // re-projected onto the surface (docs/reference/stability.md F4)
    hit.object = object;
    return hit;
  }
  const Vec3<T>& center() const { return center_; }
  T radius() const { return radius_; }
  bool robust() const { return robust_; }

 private:
  Vec3<T> center_;
  T radius_;
  bool robust_;  // see chooseArithmetic(): the textbook formula is cheaper and exact enough for small R
};

}  // namespace rt
