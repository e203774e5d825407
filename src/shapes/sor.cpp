#include "raytrace/shapes/sor.hpp"

#include <algorithm>
#include <cmath>

#include "raytrace/geometry/spawn.hpp"

namespace rt {

namespace {

// p(a + b·t) as a polynomial in t, by Horner's rule on polynomials.
Polynomial composeLinear(const Polynomial& p, double a, double b) {
  Polynomial q;
  q.c[0] = p.c[size_t(p.degree)];
  for (int i = p.degree - 1; i >= 0; --i) {
    for (int k = q.degree + 1; k > 0; --k) q.c[size_t(k)] = a * q.c[size_t(k)] + b * q.c[size_t(k - 1)];
    q.c[0] = a * q.c[0] + p.c[size_t(i)];
    ++q.degree;
  }
  return q.trimmed();
}

// Two Newton steps on x² + z² − f(u) evaluated at the ray's point itself: the root of the expanded cubic in t carries
// the rounding of its coefficients, more than the spawn offset, and a hit point below the surface by more than that
// shadows itself.
double polish(const Polynomial& f, double h0, double span, const glm::dvec3& o, const glm::dvec3& d, double t) {
  const Polynomial slope = f.derivative();
  for (int step = 0; step < 2; ++step) {
    const glm::dvec3 p = o + t * d;
    const double u = (p.y - h0) / span;
    const double g = p.x * p.x + p.z * p.z - f(u), dg = 2 * (p.x * d.x + p.z * d.z) - slope(u) * d.y / span;
    if (dg != 0) t -= g / dg;
  }
  return t;
}

}  // namespace

void SorDesc::check(const SourceLoc& at) const {
  if (points.size() < 4) {
    throw ParseError(at, "a sor needs at least 4 points, found " + std::to_string(points.size()));
  }
  // The curve's points must rise; the first and last, which only give slopes, may share their neighbour's height.
  for (size_t i = 1; i < points.size(); ++i) {
    const bool slopeOnly = i == 1 || i + 1 == points.size();
    if (!(points[i].y > points[i - 1].y || (slopeOnly && points[i].y == points[i - 1].y))) {
      throw ParseError(at, "the sor's heights must increase, but point " + std::to_string(i + 1) + "'s (" +
                               shortest(points[i].y) + ") is not above point " + std::to_string(i) + "'s (" +
                               shortest(points[i - 1].y) + ")");
    }
  }
}

// The manual's 4×4 system (§3.4.5.1.15) for r² = A·h³ + B·h² + C·h + D fixes r² at both ends and its slopes
// 2·r_j·(r_{j+1} − r_{j−1})/(h_{j+1} − h_{j−1}) there; the same cubic is written here in Hermite's form in u.
std::vector<Polynomial> SorDesc::radiusSquared() const {
  std::vector<Polynomial> segments;
  const std::vector<glm::dvec2>& p = points;
  for (size_t j = 1; j + 2 < p.size(); ++j) {
    const double span = p[j + 1].y - p[j].y;
    const double v0 = p[j].x * p[j].x, v1 = p[j + 1].x * p[j + 1].x;
    const double m0 = span * 2 * p[j].x * (p[j + 1].x - p[j - 1].x) / (p[j + 1].y - p[j - 1].y);
    const double m1 = span * 2 * p[j + 1].x * (p[j + 2].x - p[j].x) / (p[j + 2].y - p[j].y);
    Polynomial f;
    f.degree = 3;
    f.c = {v0, m0, 3 * (v1 - v0) - 2 * m0 - m1, 2 * (v0 - v1) + m0 + m1};
    segments.push_back(f.trimmed());
  }
  return segments;
}

Aabb<double> SorDesc::bounds() const {
  double most = 0, roots[2];
  for (const Polynomial& f : radiusSquared()) {
    most = std::max({most, f(0), f(1)});
    const int n = realRoots(f.derivative(), 0, 1, roots, 2);
    for (int i = 0; i < n; ++i) most = std::max(most, f(roots[i]));
  }
  const double r = std::sqrt(most);
  return {glm::dvec3(-r, points[1].y, -r), glm::dvec3(r, points[points.size() - 2].y, r)};
}

template <class T> Sor<T>::Sor(const SorDesc& desc, const Material& material, int id)
    : Object<T>(material, id),
      r2_(desc.radiusSquared()),
      open_(desc.open),
      method_(desc.sturm ? RootMethod::Sturm : RootMethod::Auto),
      bounds_(desc.bounds()) {
  for (size_t j = 1; j + 1 < desc.points.size(); ++j) heights_.push_back(desc.points[j].y);
  const double slack = 1e-7 * glm::length(bounds_.max - bounds_.min);  // rounding of the bounds and the ray
  for (size_t j = 0; j < r2_.size(); ++j) {
    // f's least and greatest on [0, 1]: at the ends or where its slope is 0.
    double turns[3];
    const int n = realRoots(r2_[j].derivative(), 0, 1, turns, 3);
    double lo = std::min(r2_[j](0), r2_[j](1)), hi = std::max(r2_[j](0), r2_[j](1));
    for (int i = 0; i < n; ++i) {
      lo = std::min(lo, r2_[j](turns[i]));
      hi = std::max(hi, r2_[j](turns[i]));
    }
    const double r0 = std::sqrt(std::max(lo, 0.0)) - slack, r1 = std::sqrt(std::max(hi, 0.0)) + slack;
    rings_.push_back({heights_[j] - slack, heights_[j + 1] + slack, r0 > 0 ? r0 * r0 : 0, r1 * r1});
  }
}

template <class T> bool Sor<T>::inside(const Vec3<T>& point) const {
  const glm::dvec3 p(point);
  if (!(heights_.front() < p.y && p.y < heights_.back())) return false;
  const size_t j = size_t(std::upper_bound(heights_.begin(), heights_.end(), p.y) - heights_.begin()) - 1;
  const double u = (p.y - heights_[j]) / (heights_[j + 1] - heights_[j]);
  return p.x * p.x + p.z * p.z < r2_[j](u);
}

template <class T> std::optional<Hit<T>> Sor<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const glm::dvec3 o(ray.origin), d(ray.dir);
  double best = double(range.max);
  glm::dvec3 normal(0);
  // The wall: |o_xz + t·d_xz|² − f(u(t)) on the t where the ray is within the segment's heights.
  Polynomial distance;
  distance.degree = 2;
  distance.c = {o.x * o.x + o.z * o.z, 2 * (o.x * d.x + o.z * d.z), d.x * d.x + d.z * d.z};
  double roots[3];
  for (size_t j = 0; j < r2_.size(); ++j) {
    if (rings_[j].missedBy(o, d, double(range.min), best)) continue;
    const double h0 = heights_[j], span = heights_[j + 1] - h0;
    double lo = double(range.min), hi = best;
    if (d.y != 0) {
      const double ta = (h0 - o.y) / d.y, tb = (h0 + span - o.y) / d.y;
      lo = std::max(lo, std::min(ta, tb));
      hi = std::min(hi, std::max(ta, tb));
    } else if (!(h0 <= o.y && o.y <= h0 + span)) {
      continue;
    }
    if (!(lo < hi)) continue;
    const Polynomial f = composeLinear(r2_[j], (o.y - h0) / span, d.y / span);
    Polynomial g = distance;
    g.degree = std::max(g.degree, f.degree);
    for (int i = 0; i <= f.degree; ++i) g.c[size_t(i)] -= f.c[size_t(i)];
    const int n = realRoots(g.trimmed(), lo, hi, roots, 3, method_);
    for (int i = 0; i < n; ++i) {
      const double t = polish(r2_[j], h0, span, o, d, roots[i]);
      const glm::dvec3 p = o + t * d;
      // The gradient of x² + z² − f, halved: f's slope in h is its slope in u over the span.
      const double slope = r2_[j].derivative()((p.y - h0) / span) / span;
      const glm::dvec3 across = glm::normalize(glm::dvec3(p.x, -slope / 2, p.z));
      if (!(double(range.min) < t && t < best) || nearSpawnOffset(t, o, d, across)) continue;
      best = t;
      normal = across;
      break;
    }
  }
  if (!open_ && d.y != 0) {
    for (const bool top : {false, true}) {
      const double h = top ? heights_.back() : heights_.front();
      const double t = (h - o.y) / d.y;
      if (!(double(range.min) < t && t < best)) continue;
      const double x = o.x + t * d.x, z = o.z + t * d.z;
      if (x * x + z * z > (top ? r2_.back()(1) : r2_.front()(0))) continue;
      best = t;
      normal = glm::dvec3(0, top ? 1 : -1, 0);
    }
  }
  return hitBefore<T>(this, o, d, best, normal, range);
}

template class Sor<float>;
template class Sor<double>;

}  // namespace rt
