#include "raytrace/shapes/isosurface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

namespace {

// How much finer than `accuracy` a crossing found is bisected, and how far from a ray's start (in accuracies) a
// crossing or the container's face is ignored: a ray leaving a hit (shadow, reflection, refraction) starts
// within kRefine·accuracy of the surface, on either side, and must not find it again there.
constexpr double kRefine = 1e-4, kSkip = 1e-2;
constexpr int kMaxDepth = 64;  // subdivisions of a stretch: more than double's bits of t

struct Stretch {
  double near, far;
  glm::dvec3 nearNormal, farNormal;  // the container's outward normals where the ray enters and leaves it
};

}  // namespace

template <class T> bool Isosurface<T>::inContainer(const glm::dvec3& p) const {
  if (d_.sphere) return glm::length(p - d_.center) <= d_.radius;
  return glm::all(glm::greaterThanEqual(p, d_.min)) && glm::all(glm::lessThanEqual(p, d_.max));
}

template <class T> std::optional<Aabb<T>> Isosurface<T>::bounds() const {
  if (d_.sphere) return Aabb<T>{Vec3<T>(d_.center - d_.radius), Vec3<T>(d_.center + d_.radius)};
  return Aabb<T>{Vec3<T>(d_.min), Vec3<T>(d_.max)};
}

// POV-Ray's normal: forward differences one `accuracy` long (measured with trace() on povray, where it differs
// from the true gradient most, at a ridge's crest: tests/shapes/test_isosurface.cpp).
template <class T> glm::dvec3 Isosurface<T>::gradient(const glm::dvec3& p) const {
  const double h = d_.accuracy;
  const Function& f = *d_.function;
  const double here = f.at(p);
  return {f.at(p + glm::dvec3(h, 0, 0)) - here, f.at(p + glm::dvec3(0, h, 0)) - here,
          f.at(p + glm::dvec3(0, 0, h)) - here};
}

template <class T>
std::optional<Hit<T>> Isosurface<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const glm::dvec3 o(ray.origin), dir(ray.dir);
  // The ray's stretch inside the container.
  Stretch s{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), {}, {}};
  if (d_.sphere) {
    const glm::dvec3 oc = o - d_.center;
    const double a = glm::dot(dir, dir), b = glm::dot(oc, dir), c = glm::dot(oc, oc) - d_.radius * d_.radius;
    const double disc = b * b - a * c;
    if (!(disc >= 0)) return std::nullopt;
    const double root = std::sqrt(disc);
    s.near = (-b - root) / a;
    s.far = (-b + root) / a;
    s.nearNormal = (o + s.near * dir - d_.center) / d_.radius;
    s.farNormal = (o + s.far * dir - d_.center) / d_.radius;
  } else {
    for (int i = 0; i < 3; ++i) {
      if (dir[i] == 0) {
        if (o[i] < d_.min[i] || o[i] > d_.max[i]) return std::nullopt;
        continue;
      }
      double ta = (d_.min[i] - o[i]) / dir[i], tb = (d_.max[i] - o[i]) / dir[i];
      glm::dvec3 na(0), nb(0);
      na[i] = -1;
      nb[i] = 1;
      if (ta > tb) {
        std::swap(ta, tb);
        std::swap(na, nb);
      }
      if (ta > s.near) {
        s.near = ta;
        s.nearNormal = na;
      }
      if (tb < s.far) {
        s.far = tb;
        s.farNormal = nb;
      }
    }
  }
  const double speed = glm::length(dir);  // object-space length of a unit of t
  const double start = double(range.min) + d_.accuracy * kSkip / speed;
  const double lo = std::max(s.near, start), hi = std::min(s.far, double(range.max));
  if (!(lo < hi)) return std::nullopt;

  const Function& f = *d_.function;
  const double threshold = d_.threshold;
  const auto g = [&](double t) { return f.at(o + t * dir) - threshold; };
  const auto hit = [&](double t, const glm::dvec3& normal) {
    Hit<T> h;
    h.t = T(t);
    h.point = Vec3<T>(o + t * dir);
    h.normal = Vec3<T>(glm::normalize(normal));
    h.object = this;
    return h;
  };
  const double gLo = g(lo);
  // The container's own face where the ray enters it inside the solid.
  if (!d_.open && s.near >= start && gLo < 0) return hit(s.near, s.nearNormal);

  // Depth-first over halves, nearer half first; a piece is skipped when its ends are further from the threshold
  // than max_gradient lets the function come back within its length.
  struct Piece {
    double a, ga, b, gb;
    int depth;
  };
  Piece stack[kMaxDepth + 1];
  int top = 0;
  stack[top++] = {lo, gLo, hi, g(hi), 0};
  while (top > 0) {
    const Piece p = stack[--top];
    const double length = (p.b - p.a) * speed;
    const bool crosses = (p.ga < 0) != (p.gb < 0);
    if (!crosses && std::abs(p.ga) + std::abs(p.gb) > d_.maxGradient * length) continue;
    if (length < d_.accuracy || p.depth == kMaxDepth) {
      if (!crosses) continue;
      double a = p.a, b = p.b, ga = p.ga;
      while ((b - a) * speed > d_.accuracy * kRefine) {
        const double m = (a + b) / 2, gm = g(m);
        if ((gm < 0) == (ga < 0)) {
          a = m;
          ga = gm;
        } else {
          b = m;
        }
      }
      const double t = (a + b) / 2;
      const glm::dvec3 n = gradient(o + t * dir);
      return hit(t, glm::length(n) > 0 ? n : -dir);
    }
    const double m = (p.a + p.b) / 2, gm = g(m);
    stack[top++] = {m, gm, p.b, p.gb, p.depth + 1};
    stack[top++] = {p.a, p.ga, m, gm, p.depth + 1};
  }
  // The container's face where the ray leaves it from inside the solid.
  if (!d_.open && s.far < double(range.max) && g(s.far) < 0) return hit(s.far, s.farNormal);
  return std::nullopt;
}

template class Isosurface<float>;
template class Isosurface<double>;

}  // namespace rt
