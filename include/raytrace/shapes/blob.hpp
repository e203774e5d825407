#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/geometry/polynomial.hpp"
#include "raytrace/geometry/transform.hpp"
#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Blob;

// A blob's component: a ball around `a`, or with `cylinder` the capsule around the segment a–b (POV-Ray's
// cylinder component has hemispherical caps), moved by its own transforms.
struct BlobComponent {
  glm::dvec3 a{0}, b{0};
  double radius = 1, strength = 1;
  bool cylinder = false;
  std::vector<TransformStep> transforms;
};

// What a file says of a blob: `blob { threshold T  sphere { c, r, [strength] s }…  cylinder { a, b, r,
// [strength] s }…  component s, r, c… [sturm] [hierarchy] }`. POV-Ray's field (3.7 manual §3.4.5.1.1): each
// component adds strength·(1 − (min(distance, r)/r)²)², distance from its centre or axis; the surface is where
// the sum equals the threshold, solid where it is greater.
struct BlobDesc {
  double threshold = 1;
  std::vector<BlobComponent> components;
  bool sturm = false;  // POV-Ray's `sturm`, a modifier (povray/scene_builder)

  static bool named(std::string_view word) { return word == "blob"; }
  static const char* name() { return "Blob"; }
  static constexpr bool kFloatErrorBound = false;  // quartic roots, computed in double

  template <class Reader> static BlobDesc read(Reader& r, std::string_view) {
    BlobDesc blob;
    const SourceLoc at = r.here();
    for (;;) {
      if (r.keyword("threshold")) {
        blob.threshold = r.positive("the blob threshold");
      } else if (r.keyword("component")) {  // the obsolete `component strength, radius, center`
        BlobComponent c;
        c.strength = r.number("the blob component strength");
        r.comma("after the blob component strength");
        c.radius = r.positive("the blob component radius");
        r.comma("after the blob component radius");
        c.a = c.b = r.vec3("the blob component center");
        blob.components.push_back(c);
      } else if (!r.block("sphere", [&](auto& s) { blob.components.push_back(component(s, false)); }) &&
                 !r.block("cylinder", [&](auto& s) { blob.components.push_back(component(s, true)); })) {
        break;
      }
    }
    if (blob.components.empty()) throw ParseError(at, "expected a sphere or cylinder component inside 'blob'");
    return blob;
  }
  double smallestFeature() const;
  Ball boundingBall() const;
  FlatFaces flatFaces() const { return {}; }  // curved, and computed in double
  void describe(std::ostream& out) const;
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const;

 private:
  template <class Reader> static BlobComponent component(Reader& r, bool cylinder) {
    BlobComponent c;
    c.cylinder = cylinder;
    c.a = c.b = r.vec3(cylinder ? "the blob cylinder's first end" : "the blob sphere center");
    r.comma("after the blob component's point");
    if (cylinder) {
      c.b = r.vec3("the blob cylinder's second end");
      r.comma("after the blob cylinder's second end");
    }
    c.radius = r.positive("the blob component radius");
    r.comma("after the blob component radius");
    r.keyword("strength");
    c.strength = r.number("the blob component strength");
    c.transforms = r.transforms();
    return c;
  }
};

// The field along a ray is, on each stretch where the same components reach it, a sum of quartics in t, whose
// roots against the threshold are the crossings (the manual's density with distance² quadratic in t).
template <class T> class Blob final : public Object<T> {
 public:
  // A component in its own space, where it is the ball or capsule around a–b.
  struct Part {
    glm::dvec3 a, axis;  // axis = b − a, zero for a ball
    double radius2, strength;
    glm::dmat4 fromWorld;  // world (the blob's space) to the component's
  };
  Blob(std::vector<Part> parts, double threshold, RootMethod method, const Aabb<T>& box, const Material& material,
       int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return box_; }
  bool inside(const Vec3<T>& p) const override { return field(glm::dvec3(p)) > threshold_; }
  const char* name() const override { return BlobDesc::name(); }

 private:
  double field(const glm::dvec3& p) const;
  glm::dvec3 gradient(const glm::dvec3& p) const;

  std::vector<Part> parts_;
  double threshold_;
  RootMethod method_;
  Aabb<T> box_;
};

}  // namespace rt
