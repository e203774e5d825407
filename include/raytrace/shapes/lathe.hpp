#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/shapes/spline2d.hpp"

namespace rt {

template <class T> class Lathe;

// What a file says of a lathe: `lathe { [linear_spline|quadratic_spline|cubic_spline|bezier_spline] N, <r, y>, … }`,
// POV-Ray's 2-D spline in the x-y plane turned about the y axis (manual §3.4.5.1.8). The curve is not closed for you; a
// point is inside when a horizontal half-line from it in the curve's plane crosses the curve an odd number of times.
struct LatheDesc {
  SplineKind spline = SplineKind::Linear;
  std::vector<glm::dvec2> points;  // (radius, height)
  bool sturm = false;              // POV-Ray's `sturm`, a modifier (povray/scene_builder)

  static bool named(std::string_view word) { return word == "lathe"; }
  static const char* name() { return "Lathe"; }
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static LatheDesc read(Reader& r, std::string_view) {
    LatheDesc d;
    readSplineKeyword(r, d.spline);
    SplinePoints list = readSplinePoints(r, "lathe");
    d.points = std::move(list.points);
    d.check(list.at);
    return d;
  }
  // The spline's segments: n − 1 linear, n − 2 quadratic, n − 3 cubic, n / 4 Bezier (manual §3.4.5.1.8).
  std::vector<Segment2> segments() const;
  // Too few points for the spline, or a Bezier count not a multiple of 4, stops at `at`.
  void check(const SourceLoc& at) const;
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
    out << "- Spline: " << splineName(spline) << "\n- Points: " << points.size()
        << "\n- Sturm: " << (sturm ? "yes" : "no") << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Lathe<T>>(*this, b.material, b.id);
  }
};

// Each segment (R(s), Y(s)) met by a ray: with t = (Y(s) − o.y)/d.y, the ray's squared distance from the axis equals
// R(s)², a polynomial of degree up to 6 in s; a level ray meets Y(s) = o.y instead, a cubic, and then a quadratic in t.
// Computed in double whatever T is. A segment is solved only for rays that pass through the ring around it.
template <class T> class Lathe final : public Object<T> {
 public:
  Lathe(const LatheDesc& desc, const Material& material, int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return Aabb<T>{Vec3<T>(bounds_.min), Vec3<T>(bounds_.max)}; }
  bool inside(const Vec3<T>& p) const override;
  const char* name() const override { return LatheDesc::name(); }

 private:
  std::vector<Segment2> segments_;
  std::vector<Ring> rings_;  // one per segment
  RootMethod method_;
  Aabb<double> bounds_;
  double probe_;  // how far off the surface a point is tested, to turn the normal outward
};

}  // namespace rt
