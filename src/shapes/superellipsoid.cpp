#include "raytrace/shapes/superellipsoid.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

// The ray's steps between samples of f: enough to find the thin rounded edges of small exponents; a ray that
// enters and leaves between two samples, grazing an edge, is missed.
constexpr int kSamples = 96;
constexpr int kBisections = 64;  // more than double's 53 bits of t

}  // namespace

template <class T> double Superellipsoid<T>::f(const glm::dvec3& p) const {
  const double a = std::pow(std::abs(p.x), 2 / e_) + std::pow(std::abs(p.y), 2 / e_);
  return std::pow(a, e_ / n_) + std::pow(std::abs(p.z), 2 / n_) - 1;
}

// ∇f without its common factor 2/n: ∂f/∂x = A^(e/n − 1)·|x|^(2/e − 1)·sign x with A = |x|^(2/e) + |y|^(2/e),
// ∂f/∂z = |z|^(2/n − 1)·sign z. On an edge of a pinched shape (e or n above 2) it is infinite or undefined:
// the direction from the centre stands in for it there.
template <class T> glm::dvec3 Superellipsoid<T>::normal(const glm::dvec3& p) const {
  const glm::dvec3 m = glm::abs(p);
  const double a = std::pow(m.x, 2 / e_) + std::pow(m.y, 2 / e_);
  const double ring = std::pow(a, e_ / n_ - 1);
  const glm::dvec3 g(ring * std::pow(m.x, 2 / e_ - 1) * (p.x < 0 ? -1 : 1),
                     ring * std::pow(m.y, 2 / e_ - 1) * (p.y < 0 ? -1 : 1),
                     std::pow(m.z, 2 / n_ - 1) * (p.z < 0 ? -1 : 1));
  const double length = glm::length(g);
  if (std::isfinite(length) && length > 0) return g / length;
  return glm::normalize(p);
}

// f sampled along the ray's stretch through the box, then the first change of side bisected. The hit is the
// bracket's far end, on the new side: a next call starting there starts on that side and moves on.
template <class T>
std::optional<Hit<T>> Superellipsoid<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const glm::dvec3 o(ray.origin), d(ray.dir);
  double near = double(range.min), far = double(range.max);
  for (int i = 0; i < 3; ++i) {
    const double slack = 1 + 1e-9;  // the surface touches the box
    const double ta = (-slack - o[i]) / d[i], tb = (slack - o[i]) / d[i];
    if (std::isnan(ta) || std::isnan(tb)) {
      if (std::abs(o[i]) > slack) return std::nullopt;  // parallel to the slab and outside it
      continue;
    }
    near = std::max(near, std::min(ta, tb));
    far = std::min(far, std::max(ta, tb));
  }
  if (!(near < far)) return std::nullopt;
  const auto in = [&](double t) { return f(o + t * d) < 0; };
  const bool startIn = in(near);
  // g > 0 on the start's side: a sample where it dips between its neighbours without changing sign may hide a
  // grazing pair of crossings, which a search for its least value between them finds.
  const auto g = [&](double t) { return startIn ? -f(o + t * d) : f(o + t * d); };
  double lo = near, before = near, gBefore = g(near), gLo = gBefore;
  for (int s = 1; s <= kSamples; ++s) {
    double hi = near + (far - near) * s / kSamples;
    const double gHi = g(hi);
    if (in(hi) == startIn && s > 1 && gLo < gBefore && gLo < gHi) {
      double a = before, b = hi;  // golden-section search for g's least value in (before, hi)
      for (int k = 0; k < kBisections && in((a + b) / 2) == startIn; ++k) {
        const double m1 = b - (b - a) * 0.6180339887498949, m2 = a + (b - a) * 0.6180339887498949;
        (g(m1) < g(m2) ? b : a) = g(m1) < g(m2) ? m2 : m1;
      }
      if (in((a + b) / 2) != startIn) {
        hi = (a + b) / 2;
        lo = before;
      }
    }
    if (in(hi) == startIn) {
      before = lo;
      gBefore = gLo;
      lo = hi;
      gLo = gHi;
      continue;
    }
    for (int b = 0; b < kBisections; ++b) {
      const double mid = lo + (hi - lo) / 2;
      if (mid <= lo || mid >= hi) break;
      (in(mid) == startIn ? lo : hi) = mid;
    }
    if (!range.surrounds(T(hi))) return std::nullopt;
    Hit<T> hit;
    hit.t = T(hi);
    hit.point = Vec3<T>(o + hi * d);
    hit.normal = Vec3<T>(normal(o + hi * d));
    hit.object = this;
    return hit;
  }
  return std::nullopt;
}

template class Superellipsoid<float>;
template class Superellipsoid<double>;

}  // namespace rt
