#pragma once

#include <memory>
#include <ostream>
#include <string_view>
#include <vector>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Polygon;

// What a file says of a polygon: `polygon { n, p1, p2, … pn }`, POV-Ray's flat shape of the points of their
// plane that lie inside an odd number of its sub-polygons, each closed by repeating its first point, the last
// one closed if it is not (the manual's §3.4.5.2.5).
struct PolygonDesc {
  std::vector<glm::dvec3> points;

  static bool named(std::string_view word) { return word == "polygon"; }
  static const char* name() { return "Polygon"; }
  // Its test is a plane's and a crossing count's, but no bound on float's error on them is proven and tested yet.
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static PolygonDesc read(Reader& r, std::string_view) {
    PolygonDesc d;
    const SourceLoc countAt = r.here();
    const double n = r.number("the number of polygon points");
    if (!(n >= 3 && n == double(size_t(n)))) {
      throw ParseError(countAt, "a polygon needs a whole number of points, at least 3, found " + shortest(n));
    }
    for (size_t i = 0; i < size_t(n); ++i) {
      r.comma(i == 0 ? "after the number of polygon points" : "after a polygon point");
      d.points.push_back(r.vec3("a polygon point"));
    }
    d.check(countAt);
    return d;
  }
  // The unit normal of the points' plane (Newell's method: the sum of the edges' cross terms), zero when they
  // span no plane.
  glm::dvec3 normal() const;
  double smallestFeature() const;
  Ball boundingBall() const;
  FlatFaces flatFaces() const { return {}; }  // computed in double (kFloatErrorBound): no offset to check
  void describe(std::ostream& out) const {
    out << "- Points: " << points.size() << "\n- Normal: " << braces(normal()) << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Polygon<T>>(*this, b.material, b.id);
  }

 private:
  // As POV-Ray: points in a plane, and the plane defined.
  void check(const SourceLoc& at) const;
};

template <class T> class Polygon final : public Object<T> {
 public:
  Polygon(const PolygonDesc& d, const Material& material, int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override;
  bool inside(const Vec3<T>&) const override { return false; }  // flat: it encloses nothing
  const char* name() const override { return PolygonDesc::name(); }

 private:
  // Whether the point (s, t) of the plane lies inside an odd number of the sub-polygons.
  bool covers(T s, T t) const;

  Vec3<T> origin_, normal_, sAxis_, tAxis_;  // the plane, and two unit axes in it
  std::vector<std::array<T, 4>> edges_;       // (s, t) of each edge's ends
  Aabb<T> box_;
};

}  // namespace rt
