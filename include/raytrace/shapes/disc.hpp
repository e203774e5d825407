#pragma once

#include <algorithm>
#include <memory>
#include <ostream>
#include <string_view>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Disc;

// What a file says of a disc: `disc { center, normal, radius [, hole] }`, POV-Ray's flat ring of the points
// of the plane through `center` across `normal` whose distance from the centre lies between the hole's radius
// and the radius (POV-Ray 3.7 manual §3.4.5.2.2).
struct DiscDesc {
  glm::dvec3 center, normal;
  double radius, hole = 0;

  static bool named(std::string_view word) { return word == "disc"; }
  static const char* name() { return "Disc"; }
  // Its test is a plane's and a distance's, but no bound on float's error on them is proven and tested yet.
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static DiscDesc read(Reader& r, std::string_view) {
    DiscDesc d;
    d.center = r.vec3("the disc center");
    r.comma("after the disc center");
    const SourceLoc normalAt = r.here();
    d.normal = r.vec3("the disc normal");
    if (d.normal == glm::dvec3(0)) throw ParseError(normalAt, "the disc normal is zero");
    r.comma("after the disc normal");
    d.radius = r.positive("the disc radius");
    if (r.moreNumbers()) {
      r.comma("after the disc radius");
      const SourceLoc holeAt = r.here();
      d.hole = r.nonNegative("the disc hole radius");
      if (d.hole >= d.radius) {
        throw ParseError(holeAt, "the disc hole radius must be smaller than its radius, found " + shortest(d.hole));
      }
    }
    return d;
  }
  double smallestFeature() const { return hole > 0 ? std::min(hole, radius - hole) : radius; }
  Ball boundingBall() const { return {center, radius}; }
  FlatFaces flatFaces() const { return {}; }  // computed in double (kFloatErrorBound): no offset to check
  void describe(std::ostream& out) const {
    out << "- Center: " << braces(center) << "\n- Normal: " << braces(normal) << "\n- Radius: " << fixed4(radius)
        << "\n- Hole radius: " << fixed4(hole) << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Disc<T>>(Vec3<T>(center), Vec3<T>(glm::normalize(normal)), T(radius), T(hole),
                                     b.material, b.id);
  }
};

template <class T> class Disc final : public Object<T> {
 public:
  Disc(const Vec3<T>& center, const Vec3<T>& normal, T radius, T hole, const Material& material, int id)
      : Object<T>(material, id), center_(center), normal_(normal), radius_(radius), hole_(hole) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override;
  // The manual's: the inside of the disc's plane, the side its normal points away from, unbounded by the radius.
  bool inside(const Vec3<T>& p) const override { return glm::dot(normal_, p - center_) < T(0); }
  const char* name() const override { return DiscDesc::name(); }

 private:
  Vec3<T> center_, normal_;  // unit normal
  T radius_, hole_;
};

}  // namespace rt
