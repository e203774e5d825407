#pragma once

#include <limits>
#include <memory>
#include <ostream>
#include <string_view>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Plane;

// What a file says of a plane: `plane { normal, distance }`, n·p = distance with the normal as written.
struct PlaneDesc {
  glm::dvec3 normal;
  double distance;

  static bool named(std::string_view word) { return word == "plane"; }
  static const char* name() { return "Plane"; }
  static constexpr bool kFloatErrorBound = true;

  template <class Reader> static PlaneDesc read(Reader& r, std::string_view) {
    const SourceLoc at = r.here();
    const glm::dvec3 n = r.vec3("the plane normal");
    if (n == glm::dvec3(0)) throw ParseError(at, "the plane normal is zero");
    r.comma("after the plane normal");
    return {n, r.number("the plane distance")};
  }
  double smallestFeature() const { return std::numeric_limits<double>::infinity(); }  // no silhouette
  Ball boundingBall() const { return {distance * glm::normalize(normal), 0}; }  // its point nearest the origin
  FlatFaces flatFaces() const { return {}; }  // unbounded: its own check (scene/tier_domain)
  void describe(std::ostream& out) const {
    out << "- Normal: " << braces(normal) << "\n- Distance: " << fixed4(distance) << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Plane<T>>(Vec3<T>(glm::normalize(normal)), T(distance), b.material, b.id);
  }
};

// The plane n·p = d with unit n. POV-Ray semantics: the file's normal is normalized and d is the distance
// from the origin along it.
template <class T> class Plane final : public Object<T> {
 public:
  Plane(const Vec3<T>& normal, T distance, const Material& material, int id)
      : Object<T>(material, id), normal_(normal), distance_(distance) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  void closerHits(const Ray<T>* rays, int n, Interval<T> range, std::optional<Hit<T>>* best) const override;
  uint32_t occludes(const Ray<T>* rays, const Interval<T>* ranges, uint32_t open) const override;
  std::optional<Aabb<T>> bounds() const override { return std::nullopt; }
  // POV-Ray's solid plane: the half-space the normal points away from.
  bool inside(const Vec3<T>& p) const override { return glm::dot(normal_, p) < distance_; }
  const char* name() const override { return PlaneDesc::name(); }

 private:
  // Where the ray meets the plane; ±∞ or NaN when it runs parallel to it, which no interval surrounds.
  T distanceAlong(const Ray<T>& ray) const {
    return (distance_ - glm::dot(normal_, ray.origin)) / glm::dot(normal_, ray.dir);
  }
  Hit<T> hitAt(const Ray<T>& ray, T t) const;

  Vec3<T> normal_;
  T distance_;
};

}  // namespace rt
