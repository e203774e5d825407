#include "raytrace/shapes/prism.hpp"

#include <algorithm>
#include <cmath>

#include "raytrace/geometry/spawn.hpp"

namespace rt {

namespace {

// A segment's ends are shared with its neighbours: a root just past them still counts, so a ray through a joint meets
// one of the two.
constexpr double kEndSlack = 1e-9;

ParseError unclosed(const SourceLoc& at, SplineKind spline, size_t first) {
  return ParseError(at, std::string("the prism's ") + splineName(spline) + "_spline loop starting at point " +
                            std::to_string(first + 1) + " does not close");
}

}  // namespace

// Each loop as the manual gives it: linear, its first point repeated (the last loop closed for you); quadratic, a
// control point, then the curve until its first point comes again; cubic, the same and one control point after; Bezier,
// four points a segment until one ends at the loop's first point.
std::vector<Segment2> PrismDesc::prismOutline(SplineKind spline, const std::vector<glm::dvec2>& p,
                                              const SourceLoc& at) {
  static constexpr size_t kLeast[] = {3, 4, 5, 4};
  if (p.size() < kLeast[size_t(spline)]) {
    throw ParseError(at, std::string("a ") + splineName(spline) + "_spline prism needs at least " +
                             std::to_string(kLeast[size_t(spline)]) + " points, found " + std::to_string(p.size()));
  }
  if (spline == SplineKind::Bezier && p.size() % 4 != 0) {
    throw ParseError(at, "a bezier_spline prism needs a multiple of 4 points, found " + std::to_string(p.size()));
  }
  std::vector<Segment2> out;
  const size_t n = p.size();
  for (size_t i = 0; i < n;) {
    if (spline == SplineKind::Bezier) {
      const size_t first = i;
      bool closed = false;
      for (; !closed && i + 3 < n; i += 4) {
        out.push_back(bezierSegment(p[i], p[i + 1], p[i + 2], p[i + 3]));
        closed = p[i + 3] == p[first];
      }
      if (!closed) throw unclosed(at, spline, first);
      continue;
    }
    const size_t start = spline == SplineKind::Linear ? i : i + 1;  // the loop's first point on the curve
    size_t end = start + 1;
    while (end < n && p[end] != p[start]) ++end;
    if (spline == SplineKind::Linear) {
      for (size_t j = start; j + 1 < std::min(end + 1, n); ++j) out.push_back(linearSegment(p[j], p[j + 1]));
      if (end == n) out.push_back(linearSegment(p[n - 1], p[start]));
      i = end + 1;
    } else if (spline == SplineKind::Quadratic) {
      if (end >= n) throw unclosed(at, spline, i);
      for (size_t j = start; j < end; ++j) out.push_back(quadraticSegment(p[j - 1], p[j], p[j + 1]));
      i = end + 1;
    } else {
      if (end + 1 >= n) throw unclosed(at, spline, i);
      for (size_t j = start; j < end; ++j) out.push_back(cubicSegment(p[j - 1], p[j], p[j + 1], p[j + 2]));
      i = end + 2;
    }
  }
  return out;
}

// conic_sweep scales the outline by the height, so the box's corners are the outline's at either height.
Aabb<double> PrismDesc::bounds() const {
  glm::dvec2 lo, hi;
  segmentBounds(outline, lo, hi);
  Aabb<double> b;
  for (const double h : {height1, height2}) {
    const double scale = conic ? h : 1;
    b.expand(glm::dvec3(scale * lo.x, h, scale * lo.y));
    b.expand(glm::dvec3(scale * hi.x, h, scale * hi.y));
  }
  return b;
}

template <class T> Prism<T>::Prism(const PrismDesc& desc, const Material& material, int id)
    : Object<T>(material, id),
      outline_(desc.outline),
      conic_(desc.conic),
      open_(desc.open),
      bottom_(std::min(desc.height1, desc.height2)),
      top_(std::max(desc.height1, desc.height2)),
      method_(desc.sturm ? RootMethod::Sturm : RootMethod::Auto),
      bounds_(desc.bounds()),
      probe_(1e-7 * glm::length(bounds_.max - bounds_.min)) {
  for (const Segment2& seg : outline_) {
    glm::dvec2 lo, hi;
    segmentBounds({seg}, lo, hi);
    boxes_.push_back({lo - glm::dvec2(probe_), hi + glm::dvec2(probe_)});
  }
}

template <class T> bool Prism<T>::covers(const glm::dvec3& p) const {
  if (conic_ && p.y == 0) return false;
  const double scale = conic_ ? p.y : 1;
  return crossingsRight(outline_, glm::dvec2(p.x, p.z) / scale) % 2 == 1;
}

template <class T> bool Prism<T>::inside(const Vec3<T>& point) const {
  const glm::dvec3 p(point);
  return bottom_ < p.y && p.y < top_ && covers(p);
}

template <class T> std::optional<Hit<T>> Prism<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const glm::dvec3 o(ray.origin), d(ray.dir);
  const glm::dvec2 o2(o.x, o.z), d2(d.x, d.z);
  // The plane of the ray and the sweep's direction: a·x + b·z + k = 0 for the outline's points (x, z). Linear: the
  // vertical plane through the ray. Conic: the plane through the origin and the ray, o × d, met by the outline lifted
  // to (x, 1, z).
  const glm::dvec3 m = glm::cross(o, d);
  const double a = conic_ ? m.x : -d.z, b = conic_ ? m.z : d.x, k = conic_ ? m.y : d.z * o.x - d.x * o.z;
  double best = double(range.max);
  glm::dvec3 normal(0);
  // A linear sweep's wall is met only where the ray is between the end heights, inside a segment's box.
  double t0 = double(range.min), t1 = best;
  if (d.y != 0) {
    const double ta = (bottom_ - o.y) / d.y, tb = (top_ - o.y) / d.y;
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  }
  const auto missed = [&](const std::array<glm::dvec2, 2>& box) {
    if (conic_) return false;
    double lo = t0, hi = t1;
    for (int axis = 0; axis < 2; ++axis) {
      if (d2[axis] == 0) {
        if (o2[axis] < box[0][axis] || o2[axis] > box[1][axis]) return true;
        continue;
      }
      const double ta = (box[0][axis] - o2[axis]) / d2[axis], tb = (box[1][axis] - o2[axis]) / d2[axis];
      lo = std::max(lo, std::min(ta, tb));
      hi = std::min(hi, std::max(ta, tb));
    }
    return !(lo <= hi);
  };
  double roots[3];
  for (size_t index = 0; index < outline_.size(); ++index) {
    const Segment2& seg = outline_[index];
    if (missed(boxes_[index])) continue;
    const int n = realRoots(seg.combination(a, b, k), -kEndSlack, 1 + kEndSlack, roots, 3, method_);
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 q = seg.at(roots[i]);
      double t;
      if (conic_) {  // o + t·d parallel to the lifted point: (o + t·d) × l = 0
        const glm::dvec3 lifted(q.x, 1, q.y), across = glm::cross(d, lifted);
        t = -glm::dot(glm::cross(o, lifted), across) / glm::dot(across, across);
      } else {
        t = glm::dot(q - o2, d2) / glm::dot(d2, d2);
      }
      const double y = o.y + t * d.y;
      if (!(double(range.min) < t && t < best && bottom_ <= y && y <= top_)) continue;
      // Across the wall: the outline's tangent and the sweep's direction, (x, 1, z) for conic.
      const glm::dvec2 along = seg.tangent(roots[i]);
      glm::dvec3 n3 = conic_ ? glm::cross(glm::dvec3(along.x, 0, along.y), glm::dvec3(q.x, 1, q.y))
                             : glm::dvec3(along.y, 0, -along.x);
      n3 = glm::normalize(n3);
      if (covers(o + t * d + probe_ * n3)) n3 = -n3;
      if (nearSpawnOffset(t, o, d, n3)) continue;
      best = t;
      normal = n3;
    }
  }
  if (!open_ && d.y != 0) {
    for (const double h : {bottom_, top_}) {
      const double t = (h - o.y) / d.y;
      if (!(double(range.min) < t && t < best)) continue;
      glm::dvec3 p = o + t * d;
      p.y = h;
      if (!covers(p)) continue;
      best = t;
      normal = glm::dvec3(0, h == top_ ? 1 : -1, 0);
    }
  }
  return hitBefore<T>(this, o, d, best, normal, range);
}

template class Prism<float>;
template class Prism<double>;

}  // namespace rt
