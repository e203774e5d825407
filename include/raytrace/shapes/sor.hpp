#pragma once

#include <memory>
#include <ostream>
#include <string_view>
#include <vector>

#include "raytrace/geometry/polynomial.hpp"
#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/shapes/spline2d.hpp"

namespace rt {

template <class T> class Sor;

// What a file says of a surface of revolution: `sor { N, <r, h>, … [open] }` (POV-Ray manual §3.4.5.1.15). Between the
// heights of points 2 and N − 1 the radius squared is a cubic in the height on each interval, through the points' r²,
// its slopes at them taken from their neighbours; the first and last points only give slopes. Flat caps close both ends
// unless `open`.
struct SorDesc {
  std::vector<glm::dvec2> points;  // (radius, height), heights increasing
  bool open = false;
  bool sturm = false;  // POV-Ray's `sturm`, a modifier (povray/scene_builder)

  static bool named(std::string_view word) { return word == "sor"; }
  static const char* name() { return "Sor"; }
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static SorDesc read(Reader& r, std::string_view) {
    SorDesc d;
    SplinePoints list = readSplinePoints(r, "sor");
    d.points = std::move(list.points);
    d.check(list.at);
    d.open = r.keyword("open");
    return d;
  }
  // Fewer than 4 points, or a height below the one before (or equal, but for the first and last points), stops at `at`.
  void check(const SourceLoc& at) const;
  // Segment j's r² as a cubic in u = (h − h_j)/(h_{j+1} − h_j), u in [0, 1].
  std::vector<Polynomial> radiusSquared() const;
  Aabb<double> bounds() const;
  double smallestFeature() const {
    const Aabb<double> b = bounds();
    return std::min(b.max.x - b.min.x, b.max.y - b.min.y);
  }
  Ball boundingBall() const {
    const Aabb<double> b = bounds();
    return {(b.min + b.max) / 2.0, glm::length(b.max - b.min) / 2};
  }
  FlatFaces flatFaces() const { return {}; }  // computed in double (kFloatErrorBound): no offset to check
  void describe(std::ostream& out) const {
    out << "- Points: " << points.size() << "\n- Open: " << (open ? "yes" : "no")
        << "\n- Sturm: " << (sturm ? "yes" : "no") << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Sor<T>>(*this, b.material, b.id);
  }
};

// On a segment, with u linear in t along the ray, x² + z² − f(u) = 0 is a cubic in t; the caps are discs. Computed in
// double whatever T is.
template <class T> class Sor final : public Object<T> {
 public:
  Sor(const SorDesc& desc, const Material& material, int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return Aabb<T>{Vec3<T>(bounds_.min), Vec3<T>(bounds_.max)}; }
  bool inside(const Vec3<T>& p) const override;
  const char* name() const override { return SorDesc::name(); }

 private:
  std::vector<double> heights_;  // the segments' ends: heights_[j] to heights_[j + 1]
  std::vector<Polynomial> r2_;   // SorDesc::radiusSquared()
  std::vector<Ring> rings_;      // what each segment sweeps, to pass over the rays that miss it
  bool open_;
  RootMethod method_;
  Aabb<double> bounds_;
};

}  // namespace rt
