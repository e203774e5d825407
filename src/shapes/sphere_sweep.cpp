#include "raytrace/shapes/sphere_sweep.hpp"

#include <algorithm>
#include <limits>

#include "raytrace/geometry/roots.hpp"

namespace rt {

namespace {

// A sphere as (centre, radius), a point of the 4-D spline both are interpolated along.
glm::dvec4 asPoint(const SweepSphere& s) { return {s.center, s.radius}; }

// The spline's point at s in [0, 1] of the segment whose four control spheres are p[0..3]: the uniform cubic
// B-spline, which passes near them, or the Catmull-Rom spline, which passes through p[1] and p[2] with slopes
// (p[2] − p[0])/2 and (p[3] − p[1])/2 (manual §3.4.5.1.13: four spheres at least; the first and last only
// steer). Both as POV-Ray's pictures of sphere_sweep show them.
glm::dvec4 splineAt(SphereSweepDesc::Spline kind, const glm::dvec4* p, double s) {
  const double s2 = s * s, s3 = s2 * s;
  if (kind == SphereSweepDesc::Spline::BSpline) {
    return ((1 - s) * (1 - s) * (1 - s) * p[0] + (3 * s3 - 6 * s2 + 4) * p[1] + (-3 * s3 + 3 * s2 + 3 * s + 1) * p[2] +
            s3 * p[3]) /
           6.0;
  }
  return 0.5 * (2.0 * p[1] + (p[2] - p[0]) * s + (2.0 * p[0] - 5.0 * p[1] + 4.0 * p[2] - p[3]) * s2 +
                (-p[0] + 3.0 * p[1] - 3.0 * p[2] + p[3]) * s3);
}

// The smallest and largest of a ray's crossings of a ball, kept in [in, out].
void widen(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& c, double r, double& in, double& out) {
  double t0, t1;
  if (!robustRoots(o - c, d, r, t0, t1)) return;
  in = std::min(in, t0);
  out = std::max(out, t1);
}

// The entry and exit t of a ray through a box, by slabs (NaN-safe: a NaN leaves the bounds as they are).
bool meetsBox(const Aabb<double>& b, const glm::dvec3& o, const glm::dvec3& inv, double lo, double hi) {
  for (int i = 0; i < 3; ++i) {
    double t0 = (b.min[i] - o[i]) * inv[i], t1 = (b.max[i] - o[i]) * inv[i];
    if (t0 > t1) std::swap(t0, t1);
    lo = t0 > lo ? t0 : lo;
    hi = t1 < hi ? t1 : hi;
    if (lo > hi) return false;
  }
  return true;
}

struct Span {
  double in, out;
  size_t segment;
};

}  // namespace

std::vector<SweepSphere> SphereSweepDesc::linearSpheres() const {
  if (spline == Spline::Linear) return spheres;
  std::vector<glm::dvec4> p;
  for (const SweepSphere& s : spheres) p.push_back(asPoint(s));
  std::vector<SweepSphere> out;
  for (size_t i = 0; i + 3 < p.size(); ++i) {
    for (int k = i == 0 ? 0 : 1; k <= kSplineSteps; ++k) {
      const glm::dvec4 q = splineAt(spline, &p[i], double(k) / kSplineSteps);
      out.push_back({glm::dvec3(q), std::max(q.w, 0.0)});
    }
  }
  return out;
}

double SphereSweepDesc::smallestFeature() const {
  double least = std::numeric_limits<double>::infinity();
  for (const SweepSphere& s : linearSpheres()) {
    if (s.radius > 0) least = std::min(least, s.radius);
  }
  return std::isfinite(least) ? least : 1;
}

Ball SphereSweepDesc::boundingBall() const {
  Aabb<double> box;
  for (const SweepSphere& s : linearSpheres()) {
    box.expand(s.center - s.radius);
    box.expand(s.center + s.radius);
  }
  return {(box.min + box.max) / 2.0, glm::length(box.max - box.min) / 2};
}

template <class T>
SphereSweep<T>::SphereSweep(std::vector<SweepSphere> spheres, const Material& material, int id)
    : Object<T>(material, id) {
  for (size_t i = 0; i + 1 < spheres.size(); ++i) {
    const SweepSphere a = spheres[i], b = spheres[i + 1];
    Segment s{};
    const double length = glm::length(b.center - a.center);
    if (length <= std::abs(b.radius - a.radius)) {  // one ball holds the other: the hull is the larger one
      const SweepSphere big = a.radius >= b.radius ? a : b;
      s.c0 = big.center;
      s.r0 = s.r1 = big.radius;
    } else {
      s.c0 = a.center;
      s.axis = (b.center - a.center) / length;
      s.r0 = a.radius;
      s.r1 = b.radius;
      s.length = length;
      s.sinA = (b.radius - a.radius) / length;
      s.cosA = std::sqrt((1 - s.sinA) * (1 + s.sinA));
    }
    // The hull lies within the two balls' boxes.
    s.box.expand(a.center - a.radius);
    s.box.expand(a.center + a.radius);
    s.box.expand(b.center - b.radius);
    s.box.expand(b.center + b.radius);
    box_.expand(s.box);
    segments_.push_back(s);
  }
}

// The hull's crossings are among the balls' and the tangent cone's: ρ·cos α = r0 + x·sin α, x along the axis
// from c0 and ρ the distance from it, between the circles where the cone touches the balls, x0 = −r0·sin α and
// x1 = L − r1·sin α. The hull is convex, so it spans from the least of them to the greatest.
template <class T>
bool SphereSweep<T>::span(const Segment& s, const glm::dvec3& o, const glm::dvec3& d, double& in,
                          double& out) const {
  in = std::numeric_limits<double>::infinity();
  out = -in;
  widen(o, d, s.c0, s.r0, in, out);
  if (s.length == 0) return in <= out;
  widen(o, d, s.c0 + s.length * s.axis, s.r1, in, out);
  const glm::dvec3 w = o - s.c0;
  const double xw = glm::dot(w, s.axis), xd = glm::dot(d, s.axis);
  const double cos2 = s.cosA * s.cosA, k = s.r0 + s.sinA * xw;
  const double a = cos2 * glm::dot(d, d) - xd * xd;
  const double b = cos2 * (glm::dot(w, d) - xw * xd) - s.sinA * xd * k;
  const double c = cos2 * (glm::dot(w, w) - xw * xw) - k * k;
  const double disc = b * b - a * c;
  if (disc >= 0 && a != 0) {
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    const double x0 = -s.r0 * s.sinA, x1 = s.length - s.r1 * s.sinA;
    for (const double t : {q / a, q != 0 ? c / q : q / a}) {
      const double x = xw + t * xd;
      if (x >= x0 && x <= x1) {
        in = std::min(in, t);
        out = std::max(out, t);
      }
    }
  }
  return in <= out;
}

// The sweep's sphere nearest p is the one whose power |p − c(s)|² − r(s)² is least, at s = (x + r0·sin α)/(L·cos² α)
// (zero derivative in s), clamped to the segment; on the surface it touches p.
template <class T> SweepSphere SphereSweep<T>::nearest(const Segment& s, const glm::dvec3& p) const {
  if (s.length == 0) return {s.c0, s.r0};
  const double x = glm::dot(p - s.c0, s.axis);
  const double at = std::clamp((x + s.r0 * s.sinA) / (s.length * s.cosA * s.cosA), 0.0, 1.0);
  return {s.c0 + at * s.length * s.axis, s.r0 + at * (s.r1 - s.r0)};
}

// The union of the hulls along the ray: their spans merged in order of entry; the first end of a merged span
// past the range's start is the hit.
template <class T> std::optional<Hit<T>> SphereSweep<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const glm::dvec3 o(ray.origin), d(ray.dir);
  const glm::dvec3 inv = 1.0 / d;
  const double lo = double(range.min), hi = double(range.max);
  thread_local std::vector<Span> spans;
  spans.clear();
  for (size_t i = 0; i < segments_.size(); ++i) {
    const Segment& s = segments_[i];
    if (!meetsBox(s.box, o, inv, lo, hi)) continue;
    double in, out;
    if (span(s, o, d, in, out) && out > lo) spans.push_back({in, out, i});
  }
  if (spans.empty()) return std::nullopt;
  std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.in < b.in; });
  for (size_t i = 0; i < spans.size();) {
    const Span first = spans[i];
    Span last = first;
    for (++i; i < spans.size() && spans[i].in <= last.out; ++i) {
      if (spans[i].out > last.out) last = spans[i];
    }
    const bool entering = first.in > lo;
    const double t = entering ? first.in : last.out;
    if (!(t > lo)) continue;
    if (!(t < hi)) return std::nullopt;
    const Segment& s = segments_[entering ? first.segment : last.segment];
    // The normal points from the nearest sphere's centre; the point is re-projected onto that sphere, as the
    // cone's quadratic loses digits to cancellation that a shadow ray from the point would see.
    const SweepSphere ball = nearest(s, o + t * d);
    const glm::dvec3 n = glm::normalize(o + t * d - ball.center);
    Hit<T> hit;
    hit.t = T(t);
    hit.point = Vec3<T>(ball.center + ball.radius * n);
    hit.normal = Vec3<T>(n);
    hit.object = this;
    return hit;
  }
  return std::nullopt;
}

// Inside a hull when the least power of the sweep's spheres at p is negative (see nearest()).
template <class T> bool SphereSweep<T>::inside(const Vec3<T>& point) const {
  const glm::dvec3 p(point);
  for (const Segment& s : segments_) {
    const SweepSphere ball = nearest(s, p);
    if (glm::dot(p - ball.center, p - ball.center) < ball.radius * ball.radius) return true;
  }
  return false;
}

template class SphereSweep<float>;
template class SphereSweep<double>;

}  // namespace rt
