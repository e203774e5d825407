#pragma once

#include <cmath>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class SphereSweep;

// One sphere of a sweep's list, or of the linear sweep that stands for a spline's.
struct SweepSphere {
  glm::dvec3 center;
  double radius;
};

// What a file says of a sphere sweep: `sphere_sweep { linear_spline | b_spline | cubic_spline N, <c>, r, …
// [tolerance T] }`, the space a sphere of varying radius fills as it moves along the spline through (or near)
// the listed spheres (POV-Ray 3.7 manual §3.4.5.1.13). linear_spline needs 2 spheres, the others 4.
struct SphereSweepDesc {
  enum class Spline { Linear, BSpline, Cubic };
  Spline spline = Spline::Linear;
  std::vector<SweepSphere> spheres;
  // POV-Ray's depth tolerance against self-shading; our spawn offset (geometry/spawn) does that job, so it is
  // kept for sceneinfo only.
  double tolerance = 1e-6;

  static bool named(std::string_view word) { return word == "sphere_sweep"; }
  static const char* name() { return "SphereSweep"; }
  static constexpr bool kFloatErrorBound = false;  // computed in double

  template <class Reader> static SphereSweepDesc read(Reader& r, std::string_view) {
    SphereSweepDesc d;
    const SourceLoc kindAt = r.here();
    if (r.keyword("b_spline")) {
      d.spline = Spline::BSpline;
    } else if (r.keyword("cubic_spline")) {
      d.spline = Spline::Cubic;
    } else if (!r.keyword("linear_spline")) {
      throw ParseError(kindAt, "expected linear_spline, b_spline or cubic_spline inside 'sphere_sweep'");
    }
    const SourceLoc countAt = r.here();
    const double n = r.number("the number of sphere_sweep spheres");
    const double least = d.spline == Spline::Linear ? 2 : 4;
    if (!(n >= least && n <= 1e7 && n == std::floor(n))) {
      throw ParseError(countAt, "a " + splineWord(d.spline) + " sphere_sweep needs a whole number of at least " +
                                    shortest(least) + " spheres, found " + shortest(n));
    }
    for (size_t i = 0; i < size_t(n); ++i) {
      r.comma("after the sphere_sweep's count or radius");
      SweepSphere s;
      s.center = r.vec3("a sphere_sweep center");
      r.comma("after a sphere_sweep center");
      s.radius = r.nonNegative("a sphere_sweep radius");
      d.spheres.push_back(s);
    }
    if (r.valueNext()) {
      throw ParseError(r.here(), "more sphere_sweep spheres than the " + shortest(n) + " its count gives");
    }
    if (r.keyword("tolerance")) d.tolerance = r.positive("the sphere_sweep tolerance");
    return d;
  }
  static std::string splineWord(Spline s) {
    return s == Spline::Linear ? "linear_spline" : s == Spline::BSpline ? "b_spline" : "cubic_spline";
  }
  // The sweep as a linear one: the listed spheres themselves, or each spline segment's spheres at
  // kSplineSteps + 1 evenly spaced parameters.
  static constexpr int kSplineSteps = 64;
  std::vector<SweepSphere> linearSpheres() const;
  double smallestFeature() const;
  Ball boundingBall() const;
  FlatFaces flatFaces() const { return {}; }  // curved, and computed in double
  void describe(std::ostream& out) const {
    out << "- Spline: " << splineWord(spline) << "\n- Spheres: " << spheres.size()
        << "\n- Tolerance: " << shortest(tolerance) << "\n";
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<SphereSweep<T>>(linearSpheres(), b.material, b.id);
  }
};

// A linear sweep: each segment between two spheres sweeps their convex hull, the two balls and the frustum of
// the cone tangent to both; the shape is the union of the hulls. Computed in double whatever T is.
template <class T> class SphereSweep final : public Object<T> {
 public:
  SphereSweep(std::vector<SweepSphere> spheres, const Material& material, int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return Aabb<T>{Vec3<T>(box_.min), Vec3<T>(box_.max)}; }
  bool inside(const Vec3<T>& p) const override;
  const char* name() const override { return SphereSweepDesc::name(); }

  // The segment between sphere i and i + 1, in the terms of its hull.
  struct Segment {
    glm::dvec3 c0, axis;  // unit axis from c0 to c1; zero when one ball holds the other
    double r0, r1, length;
    double sinA, cosA;    // the tangent cone's angle: sin α = (r1 − r0)/length
    Aabb<double> box;
  };

 private:
  // The hull of segment `s` along the ray: whether it is met, and its entry and exit t.
  bool span(const Segment& s, const glm::dvec3& o, const glm::dvec3& d, double& in, double& out) const;
  // The sphere of segment s's sweep nearest p: on the hull's surface, the one that touches it there.
  SweepSphere nearest(const Segment& s, const glm::dvec3& p) const;

  std::vector<Segment> segments_;
  Aabb<double> box_;
};

}  // namespace rt
