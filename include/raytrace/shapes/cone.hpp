#pragma once

#include <algorithm>
#include <memory>
#include <ostream>
#include <string_view>

#include "raytrace/shapes/axial.hpp"
#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Cone;

// What a file says of a cone: `cone { base, base radius, cap, cap radius [open] }`.
struct ConeDesc {
  glm::dvec3 base;
  double baseRadius;
  glm::dvec3 cap;
  double capRadius;
  bool open = false;  // POV-Ray's `open`: no end disks; inside() stays the solid's, as POV-Ray's does

  static bool named(std::string_view word) { return word == "cone"; }
  static const char* name() { return "Cone"; }
  static constexpr bool kFloatErrorBound = true;

  template <class Reader> static ConeDesc read(Reader& r, std::string_view) {
    ConeDesc cone;
    const SourceLoc at = r.here();
    cone.base = r.vec3("the cone base");
    r.comma("after the cone base");
    cone.baseRadius = r.nonNegative("the cone base radius");
    r.comma("after the cone base radius");
    cone.cap = r.vec3("the cone cap");
    r.comma("after the cone cap");
    cone.capRadius = r.nonNegative("the cone cap radius");
    if (cone.base == cone.cap) throw ParseError(at, "the cone's base and cap centres are the same point");
    if (cone.baseRadius == 0 && cone.capRadius == 0) throw ParseError(at, "both cone radii are zero");
    return cone;
  }
  double smallestFeature() const { return std::min(glm::length(cap - base), std::max(baseRadius, capRadius)); }
  Ball boundingBall() const {
    return {(base + cap) / 2.0, glm::length(cap - base) / 2 + std::max(baseRadius, capRadius)};
  }
  FlatFaces flatFaces() const { return {}; }  // curved: left out of the offset check (docs/accuracy.md)
  void describe(std::ostream& out) const {
    out << "- Center 1: " << braces(base) << "\n- Radius 1: " << fixed4(baseRadius) << "\n- Center 2: "
        << braces(cap) << "\n- Radius 2: " << fixed4(capRadius) << "\n";
    if (open) out << "- Open\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Cone<T>>(Vec3<T>(base), T(baseRadius), Vec3<T>(cap), T(capRadius), b.material, b.id,
                                     open);
  }
};

// POV-Ray's `cone { base, r1, cap, r2 }`: a truncated cone whose radius goes linearly from r1 at the base to r2
// at the cap, closed by disks at both ends (a radius of 0 is a point, with no disk) unless `open`.
template <class T> class Cone final : public Object<T> {
 public:
  Cone(const Vec3<T>& base, T baseRadius, const Vec3<T>& cap, T capRadius, const Material& material, int id,
       bool open = false)
      : Object<T>(material, id),
        frame_(base, cap),
        baseRadius_(baseRadius),
        capRadius_(capRadius),
        slope_((capRadius - baseRadius) / frame_.height()),
        open_(open) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return frame_.bounds(baseRadius_, capRadius_); }
  bool inside(const Vec3<T>& p) const override {
    return frame_.inside(p, [&](T y) { return baseRadius_ + slope_ * y; });
  }
  const char* name() const override { return ConeDesc::name(); }

 private:
  Axial<T> frame_;
  T baseRadius_, capRadius_;
  T slope_;  // k: the radius at height y is r1 + k·y
  bool open_;
};

}  // namespace rt
