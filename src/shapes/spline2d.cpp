#include "raytrace/shapes/spline2d.hpp"

#include <algorithm>
#include <limits>

namespace rt {

const char* splineName(SplineKind kind) {
  switch (kind) {
    case SplineKind::Linear:
      return "linear";
    case SplineKind::Quadratic:
      return "quadratic";
    case SplineKind::Cubic:
      return "cubic";
    case SplineKind::Bezier:
      return "bezier";
  }
  return "";
}

Polynomial Segment2::combination(double a, double b, double k) const {
  Polynomial p;
  p.degree = 3;
  for (size_t i = 0; i < 4; ++i) p.c[i] = a * c[i].x + b * c[i].y;
  p.c[0] += k;
  return p.trimmed();
}

Segment2 linearSegment(glm::dvec2 from, glm::dvec2 to) { return {{from, to - from, glm::dvec2(0), glm::dvec2(0)}}; }

Segment2 quadraticSegment(glm::dvec2 before, glm::dvec2 from, glm::dvec2 to) {
  const glm::dvec2 slope = (to - before) / 2.0;
  return {{from, slope, to - from - slope, glm::dvec2(0)}};
}

// Hermite's cubic with the end slopes of Catmull and Rom.
Segment2 cubicSegment(glm::dvec2 before, glm::dvec2 from, glm::dvec2 to, glm::dvec2 after) {
  const glm::dvec2 m0 = (to - before) / 2.0, m1 = (after - from) / 2.0;
  return {{from, m0, 3.0 * (to - from) - 2.0 * m0 - m1, 2.0 * (from - to) + m0 + m1}};
}

// Bernstein's cubic written out in powers of s.
Segment2 bezierSegment(glm::dvec2 from, glm::dvec2 control1, glm::dvec2 control2, glm::dvec2 to) {
  return {{from, 3.0 * (control1 - from), 3.0 * (from - 2.0 * control1 + control2),
           to - from + 3.0 * (control1 - control2)}};
}

int crossingsRight(const std::vector<Segment2>& segments, glm::dvec2 p) {
  int count = 0;
  double roots[3];
  for (const Segment2& seg : segments) {
    if (seg.c[0].y == p.y && seg.c[0].x > p.x) ++count;
    const int n = realRoots(seg.combination(0, 1, -p.y), 0, 1, roots, 3);
    for (int i = 0; i < n; ++i) count += seg.at(roots[i]).x > p.x;
  }
  return count;
}

void segmentBounds(const std::vector<Segment2>& segments, glm::dvec2& lo, glm::dvec2& hi) {
  lo = glm::dvec2(std::numeric_limits<double>::infinity());
  hi = -lo;
  double roots[2];
  for (const Segment2& seg : segments) {
    for (const double s : {0.0, 1.0}) {
      lo = glm::min(lo, seg.at(s));
      hi = glm::max(hi, seg.at(s));
    }
    for (const auto& [a, b] : {std::pair{1.0, 0.0}, std::pair{0.0, 1.0}}) {
      const int n = realRoots(seg.combination(a, b, 0).derivative(), 0, 1, roots, 2);
      for (int i = 0; i < n; ++i) {
        lo = glm::min(lo, seg.at(roots[i]));
        hi = glm::max(hi, seg.at(roots[i]));
      }
    }
  }
}

bool Ring::missedBy(const glm::dvec3& o, const glm::dvec3& d, double t0, double t1) const {
  if (d.y != 0) {
    const double a = (y0 - o.y) / d.y, b = (y1 - o.y) / d.y;
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  } else if (o.y < y0 || o.y > y1) {
    return true;
  }
  if (!(t0 <= t1)) return true;
  const auto distance2 = [&](double t) {
    const double x = o.x + t * d.x, z = o.z + t * d.z;
    return x * x + z * z;
  };
  const double across = d.x * d.x + d.z * d.z;
  const double nearest = across > 0 ? std::clamp(-(o.x * d.x + o.z * d.z) / across, t0, t1) : t0;
  return distance2(nearest) > r1 || std::max(distance2(t0), distance2(t1)) < r0;
}

}  // namespace rt
