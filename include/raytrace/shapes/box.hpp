#pragma once

#include <algorithm>
#include <memory>
#include <ostream>
#include <string_view>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Box;

// What a file says of a box: `box { corner, corner }`, in either order.
struct BoxDesc {
  glm::dvec3 min, max;

  static bool named(std::string_view word) { return word == "box"; }
  static const char* name() { return "Box"; }
  static constexpr bool kFloatErrorBound = true;

  template <class Reader> static BoxDesc read(Reader& r, std::string_view) {
    BoxDesc box;
    box.min = r.vec3("the first box corner");
    r.comma("after the first box corner");
    box.max = r.vec3("the second box corner");
    return box;
  }
  double smallestFeature() const {
    const glm::dvec3 e = glm::abs(max - min);
    return std::min({e.x, e.y, e.z});
  }
  Ball boundingBall() const { return {(min + max) / 2.0, glm::length(max - min) / 2}; }
  FlatFaces flatFaces() const {
    const glm::dvec3 e = max - min;
    const glm::dvec3 x(e.x, 0, 0), y(0, e.y, 0), z(0, 0, e.z);
    return {{{{min, y, z}, {min + x, y, z}, {min, x, z}, {min + y, x, z}, {min, x, y}, {min + z, x, y}}}, 6};
  }
  void describe(std::ostream& out) const {
    out << "- Min: " << braces(min) << "\n- Max: " << braces(max) << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Box<T>>(Vec3<T>(min), Vec3<T>(max), b.material, b.id);
  }
};

// An axis-aligned box. POV-Ray and the course accept the two corners in any order; they are sorted here.
template <class T> class Box final : public Object<T> {
 public:
  Box(const Vec3<T>& corner0, const Vec3<T>& corner1, const Material& material, int id)
      : Object<T>(material, id), min_(glm::min(corner0, corner1)), max_(glm::max(corner0, corner1)) {}

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return Aabb<T>{min_, max_}; }
  bool inside(const Vec3<T>& p) const override {
    return glm::all(glm::greaterThan(p, min_)) && glm::all(glm::lessThan(p, max_));
  }
  const char* name() const override { return BoxDesc::name(); }

 private:
  Vec3<T> min_, max_;
};

}  // namespace rt
