// Shared by the [stability] tests (docs/reference/stability.md §2): seeded ray generators and the higher-precision
// reference that re-solves the SAME rounded inputs, so a difference is the kernel's error alone.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "raytrace/geometry/math.hpp"

namespace rt::test {

// The reference arithmetic for T: x86-64 long double (64-bit mantissa) is enough for float inputs, double
// inputs need __float128 (113 bits) (docs/reference/stability.md §2, T1).
template <class T> struct Wider;
template <> struct Wider<float> { using type = long double; };
template <> struct Wider<double> { using type = __float128; };
template <class T> using WiderT = typename Wider<T>::type;

// √x in H. For __float128 one Newton step from the long double root doubles its 64 correct bits, without
// linking libquadmath.
template <class H> H wideSqrt(H x) {
  H y = H(std::sqrt(static_cast<long double>(x)));
  if (y > H(0)) y = (y + x / y) / H(2);
  return y;
}

template <class H> struct WideVec {
  H x, y, z;
  template <class T> explicit WideVec(const Vec3<T>& v) : x(v.x), y(v.y), z(v.z) {}
  WideVec(H x_, H y_, H z_) : x(x_), y(y_), z(z_) {}
  WideVec operator-(const WideVec& o) const { return {x - o.x, y - o.y, z - o.z}; }
  WideVec operator*(H s) const { return {x * s, y * s, z * s}; }
  H dot(const WideVec& o) const { return x * o.x + y * o.y + z * o.z; }
};

// The nearest root t > 0 of |o + t·d − c| = r solved in H, or a negative number on a miss. The inputs are
// the rounded T values the kernel saw; the robust form (RTG ch. 7) keeps H's own error far below T's.
template <class T> WiderT<T> referenceSphereT(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& c, T r) {
  using H = WiderT<T>;
  const WideVec<H> f = WideVec<H>(o) - WideVec<H>(c), dd(d);
  const H a = dd.dot(dd), b = f.dot(dd), rr = H(r) * H(r);
  const WideVec<H> l = f - dd * (b / a);
  const H disc = rr - l.dot(l);
  if (disc < H(0)) return H(-1);
  const H root = wideSqrt(a * disc);
  const H q = b > H(0) ? -(b + root) : -(b - root);
  H t0 = q / a, t1 = (f.dot(f) - rr) / q;
  if (t0 > t1) std::swap(t0, t1);
  return t0 > H(0) ? t0 : t1;
}

template <class T> bool finite(const Vec3<T>& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Uniform direction on the unit sphere.
inline glm::dvec3 randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  for (;;) {
    const glm::dvec3 v(n(rng), n(rng), n(rng));
    const double len = glm::length(v);
    if (len > 1e-12) return v / len;
  }
}

// Two unit vectors that complete unit `n` to an orthonormal frame.
inline void frame(const glm::dvec3& n, glm::dvec3& e1, glm::dvec3& e2) {
  const glm::dvec3 a = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  e1 = glm::normalize(glm::cross(n, a));
  e2 = glm::cross(n, e1);
}

// A direction at `elevation` radians above the plane with normal n, at a random azimuth.
inline glm::dvec3 atElevation(const glm::dvec3& n, double elevation, std::mt19937_64& rng) {
  glm::dvec3 e1, e2;
  frame(n, e1, e2);
  const double phi = std::uniform_real_distribution<double>(0, glm::two_pi<double>())(rng);
  return std::cos(elevation) * (std::cos(phi) * e1 + std::sin(phi) * e2) + std::sin(elevation) * n;
}

// The p-quantile (0 ≤ p ≤ 1) of the values; reorders them.
inline double quantile(std::vector<double>& v, double p) {
  if (v.empty()) return 0;
  const size_t k = std::min(v.size() - 1, size_t(p * double(v.size())));
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  return v[k];
}

}  // namespace rt::test
