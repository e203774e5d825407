#pragma once

#include <memory>
#include <ostream>
#include <string_view>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/surface/function.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Isosurface;

// What a file says of an isosurface (POV-Ray 3.7 manual "Isosurface Object"): the points where a user
// function equals the threshold, solid where it is below, inside the contained_by box or sphere, whose own
// surface shows where it cuts the solid unless the isosurface is `open`. The root search subdivides the ray's
// stretch in the container until a piece is shorter than `accuracy`, skipping a piece where max_gradient
// shows the function cannot reach the threshold (docs/shapes.md).
struct IsosurfaceParams {
  std::shared_ptr<const Function> function;
  double threshold = 0, accuracy = 0.001, maxGradient = 1.1;
  bool open = false;
  bool sphere = false;                         // the container: a sphere, else a box
  glm::dvec3 min{-1}, max{1};                  // the box's corners
  glm::dvec3 center{0};                        // the sphere's centre and radius
  double radius = 1;
};

// The description holds its parameters behind a pointer: every object's description is as large as the largest
// kind's, and an isosurface's would make the description of every triangle of a mesh larger.
struct IsosurfaceDesc {
  std::shared_ptr<const IsosurfaceParams> params;

  static bool named(std::string_view word) { return word == "isosurface"; }
  static const char* name() { return "Isosurface"; }
  static constexpr bool kFloatErrorBound = false;  // an iterative root, computed in double

  template <class Reader> static IsosurfaceDesc read(Reader& r, std::string_view) {
    IsosurfaceParams d;
    const SourceLoc at = r.here();
    bool hasFunction = false;
    for (;;) {
      if (r.function(d.function)) {
        hasFunction = true;
      } else if (r.keyword("threshold")) {
        d.threshold = r.number("the isosurface threshold");
      } else if (r.keyword("accuracy")) {
        d.accuracy = r.positive("the isosurface accuracy");
      } else if (r.keyword("max_gradient")) {
        d.maxGradient = r.positive("the isosurface max_gradient");
      } else if (r.keyword("open")) {
        d.open = true;
      } else if (r.keyword("max_trace")) {
        r.number("the isosurface max_trace");  // every crossing is found, one query at a time
      } else if (r.keyword("all_intersections")) {
        continue;
      } else if (!r.block("contained_by", [&d](auto& c) {
                   if (c.block("box", [&d](auto& b) {
                         const glm::dvec3 p = b.vec3("the contained_by box corner"), q = b.vec3("the contained_by box corner");
                         d.min = glm::min(p, q);
                         d.max = glm::max(p, q);
                       })) {
                     d.sphere = false;
                   } else if (c.block("sphere", [&d](auto& s) {
                                d.center = s.vec3("the contained_by sphere centre");
                                d.radius = s.positive("the contained_by sphere radius");
                              })) {
                     d.sphere = true;
                   }
                 })) {
        break;
      }
    }
    if (!hasFunction) throw ParseError(at, "an isosurface needs a function");
    return {std::make_shared<const IsosurfaceParams>(std::move(d))};
  }
  double smallestFeature() const { return params->accuracy; }
  Ball boundingBall() const {
    const IsosurfaceParams& p = *params;
    return p.sphere ? Ball{p.center, p.radius} : Ball{(p.min + p.max) / 2.0, glm::length(p.max - p.min) / 2};
  }
  FlatFaces flatFaces() const { return {}; }  // computed in double (kFloatErrorBound): no offset to check
  void describe(std::ostream& out) const {
    const IsosurfaceParams& p = *params;
    out << "- Threshold: " << fixed4(p.threshold) << "\n- Accuracy: " << fixed4(p.accuracy)
        << "\n- Max gradient: " << fixed4(p.maxGradient) << "\n";
    if (p.sphere) out << "- Contained by sphere: " << braces(p.center) << " " << fixed4(p.radius) << "\n";
    else out << "- Contained by box: " << braces(p.min) << " " << braces(p.max) << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Isosurface<T>>(*params, b.material, b.id);
  }
};

// Computed in double whatever T is.
template <class T> class Isosurface final : public Object<T> {
 public:
  Isosurface(const IsosurfaceParams& d, const Material& material, int id) : Object<T>(material, id), d_(d) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override;
  bool inside(const Vec3<T>& p) const override {
    return inContainer(glm::dvec3(p)) && d_.function->at(glm::dvec3(p)) < d_.threshold;
  }
  const char* name() const override { return IsosurfaceDesc::name(); }

 private:
  bool inContainer(const glm::dvec3& p) const;
  glm::dvec3 gradient(const glm::dvec3& p) const;

  IsosurfaceParams d_;
};

}  // namespace rt
