// POV-Ray's 2-D splines (the lathe's and prism's curves) as cubic segments, and what both shapes ask of them: a
// segment's coordinate as a polynomial, the even-odd count of crossings, and the box around them.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/geometry/hit.hpp"
#include "raytrace/geometry/interval.hpp"
#include "raytrace/geometry/math.hpp"
#include "raytrace/geometry/polynomial.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

enum class SplineKind { Linear, Quadratic, Cubic, Bezier };

// "linear", "quadratic", "cubic", "bezier": the keyword without its "_spline".
const char* splineName(SplineKind kind);

// Takes a spline keyword if one comes next, into `kind`.
template <class Reader> bool readSplineKeyword(Reader& r, SplineKind& kind) {
  for (const SplineKind k : {SplineKind::Linear, SplineKind::Quadratic, SplineKind::Cubic, SplineKind::Bezier}) {
    if (r.keyword(std::string(splineName(k)) + "_spline")) {
      kind = k;
      return true;
    }
  }
  return false;
}

// P(s) = c[0] + c[1]·s + c[2]·s² + c[3]·s³ for s in [0, 1].
struct Segment2 {
  std::array<glm::dvec2, 4> c;

  glm::dvec2 at(double s) const { return c[0] + s * (c[1] + s * (c[2] + s * c[3])); }
  glm::dvec2 tangent(double s) const { return c[1] + s * (2.0 * c[2] + 3.0 * s * c[3]); }
  // a·x(s) + b·y(s) + k as a polynomial in s.
  Polynomial combination(double a, double b, double k) const;
};

// The segment from `from` to `to`. Quadratic: the point before it sets the slope at `from` (POV-Ray manual §3.4.5.1.8),
// (to − before)/2 as POV-Ray's pictures show; the slope at `to` is left free. Cubic: Catmull-Rom, the slopes (to −
// before)/2 and (after − from)/2. Bezier: `before` and `after` are the two control points.
Segment2 linearSegment(glm::dvec2 from, glm::dvec2 to);
Segment2 quadraticSegment(glm::dvec2 before, glm::dvec2 from, glm::dvec2 to);
Segment2 cubicSegment(glm::dvec2 before, glm::dvec2 from, glm::dvec2 to, glm::dvec2 after);
Segment2 bezierSegment(glm::dvec2 from, glm::dvec2 control1, glm::dvec2 control2, glm::dvec2 to);

// How many times the half-line from p towards +x crosses the segments: the even-odd rule's count. A segment holds its
// start and not its end, so a curve through p's line at a joint counts once.
int crossingsRight(const std::vector<Segment2>& segments, glm::dvec2 p);

// The smallest box around the segments: their ends and where a coordinate turns.
void segmentBounds(const std::vector<Segment2>& segments, glm::dvec2& lo, glm::dvec2& hi);

// The ring a piece of a surface of revolution about the y axis sweeps: its heights and its squared distances
// from the axis. A ray that misses it need not be solved against the piece.
struct Ring {
  double y0, y1, r0, r1;
  // Whether o + t·d for t in [t0, t1] stays out of the ring: never at its heights, or there always nearer the
  // axis or always farther (the squared distance from the axis is convex in t).
  bool missedBy(const glm::dvec3& o, const glm::dvec3& d, double t0, double t1) const;
};

// What a shape's read() (shapes/kind.hpp) takes for a spline: `N, <u, v>, …`, the points' first two coordinates; `at`
// is where N was, for the messages about the count.
struct SplinePoints {
  std::vector<glm::dvec2> points;
  SourceLoc at;
};
template <class Reader> SplinePoints readSplinePoints(Reader& r, const std::string& shape) {
  SplinePoints list{{}, r.here()};
  const double n = r.number(("the number of " + shape + " points").c_str());
  if (!(n >= 0 && n <= 1e7 && n == std::floor(n))) {
    throw ParseError(list.at, "the number of " + shape + " points must be a whole number, found " + shortest(n));
  }
  const std::string what = "a " + shape + " point";
  for (size_t i = 0; i < size_t(n); ++i) {
    r.comma(("after " + what).c_str());
    const glm::dvec3 p = r.vec3(what.c_str());
    list.points.emplace_back(p.x, p.y);
  }
  if (r.valueNext()) {
    throw ParseError(r.here(), "more " + shape + " points than the " + shortest(n) + " its count gives");
  }
  return list;
}

// The hit of the swept and turned shapes: the nearest t found in double, or none when it lies at or past the
// range's end.
template <class T>
std::optional<Hit<T>> hitBefore(const Object<T>* object, const glm::dvec3& o, const glm::dvec3& d, double t,
                                const glm::dvec3& normal, Interval<T> range) {
  if (!(t < double(range.max))) return std::nullopt;
  Hit<T> hit;
  hit.t = T(t);
  hit.point = Vec3<T>(o + t * d);
  hit.normal = Vec3<T>(normal);
  hit.object = object;
  return hit;
}

}  // namespace rt
