#include "raytrace/shapes/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

namespace {

// The edges of the sub-polygons: a sub-polygon ends where its first point comes again, the last one where the
// points end.
std::vector<std::pair<glm::dvec3, glm::dvec3>> edgesOf(const std::vector<glm::dvec3>& points) {
  std::vector<std::pair<glm::dvec3, glm::dvec3>> edges;
  size_t start = 0;
  for (size_t i = 1; i < points.size(); ++i) {
    if (i == start) continue;
    edges.emplace_back(points[i - 1], points[i]);
    if (points[i] == points[start]) start = i + 1;
  }
  if (start < points.size() && points.back() != points[start]) edges.emplace_back(points.back(), points[start]);
  return edges;
}

}  // namespace

glm::dvec3 PolygonDesc::normal() const {
  glm::dvec3 n(0);
  for (const auto& [a, b] : edgesOf(points)) n += glm::cross(a, b);
  return glm::length(n) > 0 ? glm::normalize(n) : glm::dvec3(0);
}

void PolygonDesc::check(const SourceLoc& at) const {
  const glm::dvec3 n = normal();
  if (n == glm::dvec3(0)) throw ParseError(at, "the polygon's points span no plane");
  double size = 0;
  for (const glm::dvec3& p : points) size = std::max(size, glm::length(p - points[0]));
  for (const glm::dvec3& p : points) {
    if (std::abs(glm::dot(p - points[0], n)) > 1e-6 * size) {
      throw ParseError(at, "the polygon's points are not in one plane");
    }
  }
}

double PolygonDesc::smallestFeature() const {
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& [a, b] : edgesOf(points)) {
    if (a != b) smallest = std::min(smallest, glm::length(b - a));
  }
  return smallest;
}

Ball PolygonDesc::boundingBall() const {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (const glm::dvec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return {(lo + hi) / 2.0, glm::length(hi - lo) / 2};
}

template <class T>
Polygon<T>::Polygon(const PolygonDesc& d, const Material& material, int id) : Object<T>(material, id) {
  const glm::dvec3 n = d.normal();
  // An axis in the plane: the normal crossed with the world axis it is least along.
  const glm::dvec3 a = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z) ? glm::dvec3(1, 0, 0)
                       : std::abs(n.y) <= std::abs(n.z)                                   ? glm::dvec3(0, 1, 0)
                                                                                          : glm::dvec3(0, 0, 1);
  const glm::dvec3 s = glm::normalize(glm::cross(n, a)), t = glm::cross(n, s);
  origin_ = Vec3<T>(d.points[0]);
  normal_ = Vec3<T>(n);
  sAxis_ = Vec3<T>(s);
  tAxis_ = Vec3<T>(t);
  for (const auto& [p, q] : edgesOf(d.points)) {
    edges_.push_back({T(glm::dot(p - d.points[0], s)), T(glm::dot(p - d.points[0], t)),
                      T(glm::dot(q - d.points[0], s)), T(glm::dot(q - d.points[0], t))});
  }
  for (const glm::dvec3& p : d.points) box_.expand(Vec3<T>(p));
}

// The even-odd rule: a ray from (s, t) along +s crosses an odd number of edges when the point is inside.
template <class T> bool Polygon<T>::covers(T s, T t) const {
  bool in = false;
  for (const auto& e : edges_) {
    if ((e[1] > t) == (e[3] > t)) continue;
    const T crossing = e[0] + (t - e[1]) / (e[3] - e[1]) * (e[2] - e[0]);
    if (crossing > s) in = !in;
  }
  return in;
}

template <class T>
std::optional<Hit<T>> Polygon<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const T denom = glm::dot(normal_, ray.dir);
  if (denom == T(0)) return std::nullopt;
  const T t = glm::dot(normal_, origin_ - ray.origin) / denom;
  if (!range.surrounds(t)) return std::nullopt;
  const Vec3<T> rel = ray.at(t) - origin_;
  const T s = glm::dot(rel, sAxis_), u = glm::dot(rel, tAxis_);
  if (!covers(s, u)) return std::nullopt;
  Hit<T> hit;
  hit.t = t;
  hit.point = origin_ + s * sAxis_ + u * tAxis_;  // on the plane by construction
  hit.normal = normal_;
  hit.object = this;
  return hit;
}

template <class T> std::optional<Aabb<T>> Polygon<T>::bounds() const { return box_; }

template class Polygon<float>;
template class Polygon<double>;

}  // namespace rt
