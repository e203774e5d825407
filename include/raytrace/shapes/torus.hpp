#pragma once

#include <memory>
#include <ostream>
#include <string_view>

#include "raytrace/shapes/algebraic.hpp"
#include "raytrace/shapes/kind.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

// What a file says of a torus: `torus { major, minor [sturm] }`, POV-Ray's ring in the x-z plane around the
// y axis, its tube's centre line `major` from the axis and the tube's radius `minor`. The surface is the quartic
// (|p|² + R² − r²)² − 4R²(x² + z²) = 0 (POV-Ray 3.7 manual §3.4.5.3.5, "a torus the hard way"), solid
// where it is negative; with major < minor the tube passes through the axis (a spindle torus).
struct TorusDesc {
  double major, minor;
  bool sturm = false;  // POV-Ray's `sturm`, a modifier (povray/scene_builder)

  static bool named(std::string_view word) { return word == "torus"; }
  static const char* name() { return "Torus"; }
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static TorusDesc read(Reader& r, std::string_view) {
    const double major = r.nonNegative("the torus major radius");
    r.comma("after the torus major radius");
    return {major, r.positive("the torus minor radius")};
  }
  double smallestFeature() const { return minor; }
  Ball boundingBall() const { return {glm::dvec3(0), major + minor}; }
  FlatFaces flatFaces() const { return {}; }  // curved, and computed in double
  void describe(std::ostream& out) const {
    out << "- Major radius: " << fixed4(major) << "\n- Minor radius: " << fixed4(minor)
        << "\n- Sturm: " << (sturm ? "yes" : "no") << "\n";
  }
  std::vector<Monomial> terms() const {
    const double sum = major * major + minor * minor, difference = major * major - minor * minor;
    return {{1, 4, 0, 0},        {1, 0, 4, 0},
            {1, 0, 0, 4},        {2, 2, 2, 0},
            {2, 2, 0, 2},        {2, 0, 2, 2},
            {-2 * sum, 2, 0, 0}, {2 * difference, 0, 2, 0},
            {-2 * sum, 0, 0, 2}, {difference * difference, 0, 0, 0}};
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    const T outer = T(major + minor);
    Aabb<T> box;
    box.expand(Vec3<T>(-outer, T(-minor), -outer));
    box.expand(Vec3<T>(outer, T(minor), outer));
    return std::make_unique<Algebraic<T>>(AlgebraicSurface(terms(), sturm ? RootMethod::Sturm : RootMethod::Auto),
                                          major + minor, box, name(), b.material, b.id);
  }
};

}  // namespace rt
