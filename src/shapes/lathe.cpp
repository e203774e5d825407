#include "raytrace/shapes/lathe.hpp"

#include <algorithm>
#include <cmath>

#include "raytrace/geometry/roots.hpp"
#include "raytrace/geometry/spawn.hpp"

namespace rt {

namespace {

Polynomial plus(Polynomial a, const Polynomial& b, double scale) {
  a.degree = std::max(a.degree, b.degree);
  for (int i = 0; i <= b.degree; ++i) a.c[size_t(i)] += scale * b.c[size_t(i)];
  return a;
}

// A segment's ends are shared with its neighbours: a root just past them still counts, so a ray through a joint meets
// one of the two.
constexpr double kEndSlack = 1e-9;

// Two Newton steps on x² + z² − R(s)² at the ray's point of height Y(s), evaluated there: the root of the expanded
// polynomial carries the rounding of its coefficients, more than the spawn offset, and a hit point below the surface by
// more than that shadows itself.
double polish(const Segment2& seg, const glm::dvec3& o, const glm::dvec3& d, double s) {
  for (int step = 0; step < 2; ++step) {
    const glm::dvec2 q = seg.at(s), slope = seg.tangent(s);
    const glm::dvec3 p = o + (q.y - o.y) / d.y * d;
    const double h = p.x * p.x + p.z * p.z - q.x * q.x;
    const double dh = 2 * (p.x * d.x + p.z * d.z) * slope.y / d.y - 2 * q.x * slope.x;
    if (dh != 0) s -= h / dh;
  }
  return s;
}

}  // namespace

std::vector<Segment2> LatheDesc::segments() const {
  std::vector<Segment2> s;
  const std::vector<glm::dvec2>& p = points;
  switch (spline) {
    case SplineKind::Linear:
      for (size_t i = 0; i + 1 < p.size(); ++i) s.push_back(linearSegment(p[i], p[i + 1]));
      break;
    case SplineKind::Quadratic:
      for (size_t i = 1; i + 1 < p.size(); ++i) s.push_back(quadraticSegment(p[i - 1], p[i], p[i + 1]));
      break;
    case SplineKind::Cubic:
      for (size_t i = 1; i + 2 < p.size(); ++i) s.push_back(cubicSegment(p[i - 1], p[i], p[i + 1], p[i + 2]));
      break;
    case SplineKind::Bezier:
      for (size_t i = 0; i + 3 < p.size(); i += 4) s.push_back(bezierSegment(p[i], p[i + 1], p[i + 2], p[i + 3]));
      break;
  }
  return s;
}

void LatheDesc::check(const SourceLoc& at) const {
  static constexpr size_t kLeast[] = {2, 3, 4, 4};
  const size_t least = kLeast[size_t(spline)];
  const std::string found = ", found " + std::to_string(points.size());
  if (points.size() < least) {
    throw ParseError(at, std::string("a ") + splineName(spline) + "_spline lathe needs at least " +
                             std::to_string(least) + " points" + found);
  }
  if (spline == SplineKind::Bezier && points.size() % 4 != 0) {
    throw ParseError(at, "a bezier_spline lathe needs a multiple of 4 points" + found);
  }
}

Aabb<double> LatheDesc::bounds() const {
  glm::dvec2 lo, hi;
  segmentBounds(segments(), lo, hi);
  const double r = std::max(std::abs(lo.x), std::abs(hi.x));
  return {glm::dvec3(-r, lo.y, -r), glm::dvec3(r, hi.y, r)};
}

template <class T> Lathe<T>::Lathe(const LatheDesc& desc, const Material& material, int id)
    : Object<T>(material, id),
      segments_(desc.segments()),
      method_(desc.sturm ? RootMethod::Sturm : RootMethod::Auto),
      bounds_(desc.bounds()),
      probe_(1e-7 * glm::length(bounds_.max - bounds_.min)) {
  const double slack = probe_;  // rounding of the bounds and of the ray's distance
  for (const Segment2& seg : segments_) {
    glm::dvec2 lo, hi;
    segmentBounds({seg}, lo, hi);
    const double r0 = lo.x > 0 ? lo.x - slack : 0, r1 = std::max(-lo.x, hi.x) + slack;
    rings_.push_back({lo.y - slack, hi.y + slack, r0 > 0 ? r0 * r0 : 0, r1 * r1});
  }
}

template <class T> bool Lathe<T>::inside(const Vec3<T>& point) const {
  const glm::dvec3 p(point);
  return crossingsRight(segments_, glm::dvec2(std::hypot(p.x, p.z), p.y)) % 2 == 1;
}

template <class T> std::optional<Hit<T>> Lathe<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const glm::dvec3 o(ray.origin), d(ray.dir);
  const glm::dvec3 oxz(o.x, 0, o.z), dxz(d.x, 0, d.z);
  const double across = glm::dot(dxz, dxz);
  // Where the ray is `radius` from the axis: the cylinder's quadratic.
  const auto tAtRadius = [&](double radius, double* ts) { return robustRoots(oxz, dxz, radius, ts[0], ts[1]) ? 2 : 0; };
  const bool level = std::abs(d.y) < 1e-9 * std::sqrt(across);
  double best = double(range.max);
  glm::dvec3 normal(0);
  // The hit at t, on the curve at s of `seg`, if it is nearer than the best so far.
  const auto consider = [&](double t, double s, const Segment2& seg) {
    if (!(double(range.min) < t && t < best)) return;
    const glm::dvec3 p = o + t * d;
    const double rho = std::hypot(p.x, p.z);
    const glm::dvec2 along = seg.tangent(s);
    glm::dvec2 side = glm::normalize(glm::dvec2(along.y, -along.x));  // in the plane (radius, height)
    if (crossingsRight(segments_, glm::dvec2(rho, p.y) + probe_ * side) % 2 == 1) side = -side;
    const glm::dvec2 out = rho > 0 ? glm::dvec2(p.x, p.z) / rho : glm::dvec2(0);
    const glm::dvec3 n = glm::normalize(glm::dvec3(side.x * out.x, side.y, side.x * out.y));
    if (nearSpawnOffset(t, o, d, n)) return;
    best = t;
    normal = n;
  };
  double roots[6], ts[2];
  for (size_t index = 0; index < segments_.size(); ++index) {
    const Segment2& seg = segments_[index];
    if (rings_[index].missedBy(o, d, double(range.min), best)) continue;
    if (level) {
      const int n = realRoots(seg.combination(0, 1, -o.y), -kEndSlack, 1 + kEndSlack, roots, 3, method_);
      for (int i = 0; i < n; ++i) {
        const int m = tAtRadius(seg.at(roots[i]).x, ts);
        for (int k = 0; k < m; ++k) consider(ts[k], roots[i], seg);
      }
      continue;
    }
    // x(s) = o.x + d.x·(Y(s) − o.y)/d.y, and z alike; x² + z² − R(s)² = 0.
    const Polynomial y = seg.combination(0, 1, 0), r = seg.combination(1, 0, 0);
    Polynomial x = y, z = y;
    for (int i = 0; i <= y.degree; ++i) {
      x.c[size_t(i)] *= d.x / d.y;
      z.c[size_t(i)] *= d.z / d.y;
    }
    x.c[0] += o.x - d.x * o.y / d.y;
    z.c[0] += o.z - d.z * o.y / d.y;
    const Polynomial f = plus(plus(times(x, x), times(z, z), 1), times(r, r), -1).trimmed();
    const int n = realRoots(f, -kEndSlack, 1 + kEndSlack, roots, 6, method_);
    for (int i = 0; i < n; ++i) {
      const double s = polish(seg, o, d, roots[i]);
      const glm::dvec2 q = seg.at(s);
      double t = (q.y - o.y) / d.y;
      // A ray closer to level than steep finds t more exactly from its distance to the axis.
      if (std::abs(d.y) * std::abs(d.y) < across) {
        const int m = tAtRadius(q.x, ts);
        if (m == 2) t = std::abs(ts[0] - t) < std::abs(ts[1] - t) ? ts[0] : ts[1];
      }
      consider(t, s, seg);
    }
  }
  return hitBefore<T>(this, o, d, best, normal, range);
}

template class Lathe<float>;
template class Lathe<double>;

}  // namespace rt
