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

template <class T> class Cylinder;

// What a file says of a cylinder: `cylinder { base, cap, radius [open] }`, capped at both ends unless open.
struct CylinderDesc {
  glm::dvec3 base, cap;
  double radius;
  bool open = false;  // POV-Ray's `open`: no end disks; inside() stays the solid's, as POV-Ray's does

  static bool named(std::string_view word) { return word == "cylinder"; }
  static const char* name() { return "Cylinder"; }
  static constexpr bool kFloatErrorBound = true;

  template <class Reader> static CylinderDesc read(Reader& r, std::string_view) {
    CylinderDesc cyl;
    const SourceLoc at = r.here();
    cyl.base = r.vec3("the cylinder base");
    r.comma("after the cylinder base");
    cyl.cap = r.vec3("the cylinder cap");
    r.comma("after the cylinder cap");
    cyl.radius = r.positive("the cylinder radius");
    if (cyl.base == cyl.cap) throw ParseError(at, "the cylinder's base and cap centres are the same point");
    return cyl;
  }
  double smallestFeature() const { return std::min(glm::length(cap - base), radius); }
  Ball boundingBall() const { return {(base + cap) / 2.0, glm::length(cap - base) / 2 + radius}; }
  FlatFaces flatFaces() const { return {}; }  // curved: left out of the offset check (docs/accuracy.md)
  void describe(std::ostream& out) const {
    out << "- Base: " << braces(base) << "\n- Cap: " << braces(cap) << "\n- Radius: " << fixed4(radius) << "\n";
    if (open) out << "- Open\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Cylinder<T>>(Vec3<T>(base), Vec3<T>(cap), T(radius), b.material, b.id, open);
  }
};

// A cylinder of radius r around the segment base→cap, closed at both ends by disks (POV-Ray's `cylinder`
// without `open`; an open one is the side alone). The .cli language's vertical `cylinder r x z ymin ymax` is the
// same shape.
template <class T> class Cylinder final : public Object<T> {
 public:
  Cylinder(const Vec3<T>& base, const Vec3<T>& cap, T radius, const Material& material, int id, bool open = false)
      : Object<T>(material, id), frame_(base, cap), radius_(radius), open_(open) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return frame_.bounds(radius_, radius_); }
  bool inside(const Vec3<T>& p) const override { return frame_.inside(p, [&](T) { return radius_; }); }
  const char* name() const override { return CylinderDesc::name(); }

 private:
  Axial<T> frame_;
  T radius_;
  bool open_;
};

}  // namespace rt
