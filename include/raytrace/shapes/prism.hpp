#pragma once

#include <memory>
#include <ostream>
#include <string_view>
#include <vector>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/shapes/spline2d.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Prism;

// What a file says of a prism: `prism { [linear_sweep|conic_sweep] [SPLINE] h1, h2, N, <x, z>, … [open] }` (POV-Ray
// manual §3.4.5.1.11): closed 2-D splines in the x-z plane swept along y from h1 to h2. A point list may hold several
// loops, each closed by repeating its first point on the curve; where an even number of them overlap is a hole (the
// even-odd rule). conic_sweep scales the outline by the height, toward the origin, so the outline as given lies at
// y = 1. Flat caps close both ends unless `open`.
struct PrismDesc {
  SplineKind spline = SplineKind::Linear;
  bool conic = false;
  double height1 = 0, height2 = 1;
  std::vector<glm::dvec2> points;  // (x, z)
  std::vector<Segment2> outline;   // the loops' segments, from the points (prismOutline)
  bool open = false;
  bool sturm = false;  // POV-Ray's `sturm`, a modifier (povray/scene_builder)

  static bool named(std::string_view word) { return word == "prism"; }
  static const char* name() { return "Prism"; }
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static PrismDesc read(Reader& r, std::string_view) {
    PrismDesc d;
    for (;;) {  // the sweep and spline keywords, in any order; the last of each counts
      if (r.keyword("linear_sweep")) {
        d.conic = false;
      } else if (r.keyword("conic_sweep")) {
        d.conic = true;
      } else if (!readSplineKeyword(r, d.spline)) {
        break;
      }
    }
    d.height1 = r.number("the prism's first height");
    r.comma("after the prism's first height");
    d.height2 = r.number("the prism's second height");
    r.comma("after the prism's second height");
    SplinePoints list = readSplinePoints(r, "prism");
    d.points = std::move(list.points);
    d.outline = prismOutline(d.spline, d.points, list.at);
    d.open = r.keyword("open");
    return d;
  }
  // The loops' segments by the manual's rules for each spline; a loop that never closes stops at `at`.
  static std::vector<Segment2> prismOutline(SplineKind spline, const std::vector<glm::dvec2>& p, const SourceLoc& at);
  Aabb<double> bounds() const;
  double smallestFeature() const {
    const Aabb<double> b = bounds();
    return std::min({b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z});
  }
  Ball boundingBall() const {
    const Aabb<double> b = bounds();
    return {(b.min + b.max) / 2.0, glm::length(b.max - b.min) / 2};
  }
  FlatFaces flatFaces() const { return {}; }  // computed in double (kFloatErrorBound): no offset to check
  void describe(std::ostream& out) const {
    out << "- Sweep: " << (conic ? "conic" : "linear") << "\n- Spline: " << splineName(spline)
        << "\n- Heights: " << fixed4(height1) << " " << fixed4(height2) << "\n- Points: " << points.size()
        << "\n- Open: " << (open ? "yes" : "no") << "\n- Sturm: " << (sturm ? "yes" : "no") << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Prism<T>>(*this, b.material, b.id);
  }
};

// A wall segment P(s) meets the ray where the plane holding the ray and the sweep's direction (vertical, or toward the
// origin for conic) holds P(s): one linear combination of x(s) and z(s), a cubic in s. Computed in double whatever T
// is.
template <class T> class Prism final : public Object<T> {
 public:
  Prism(const PrismDesc& desc, const Material& material, int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return Aabb<T>{Vec3<T>(bounds_.min), Vec3<T>(bounds_.max)}; }
  bool inside(const Vec3<T>& p) const override;
  const char* name() const override { return PrismDesc::name(); }

 private:
  // Whether the outline, at p's height, holds p (even-odd).
  bool covers(const glm::dvec3& p) const;

  std::vector<Segment2> outline_;
  std::vector<std::array<glm::dvec2, 2>> boxes_;  // each segment's box in (x, z), to pass over the rays that miss it
  bool conic_, open_;
  double bottom_, top_;
  RootMethod method_;
  Aabb<double> bounds_;
  double probe_;  // how far off the surface a point is tested, to turn the normal outward
};

}  // namespace rt
