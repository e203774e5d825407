#include "raytrace/shapes/algebraic.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "raytrace/util/format.hpp"

namespace rt {

std::vector<Monomial> povPolyTerms(int order, const std::vector<double>& coefficients) {
  std::vector<Monomial> terms;
  size_t k = 0;
  for (int x = order; x >= 0; --x) {
    for (int y = order - x; y >= 0; --y) {
      for (int z = order - x - y; z >= 0; --z, ++k) {
        if (coefficients[k] != 0) terms.push_back({coefficients[k], x, y, z});
      }
    }
  }
  return terms;
}

std::string termsText(const std::vector<Monomial>& terms) {
  std::string text;
  for (const Monomial& m : terms) {
    if (!text.empty()) text += ", ";
    text += fixed4(m.c);
    for (const auto& [name, power] : {std::pair{" x", m.x}, {" y", m.y}, {" z", m.z}}) {
      if (power > 0) text += name;
      if (power > 1) text += "^" + std::to_string(power);
    }
  }
  return text;
}

namespace {

constexpr int kMax = Polynomial::kMaxDegree;
using Powers = std::array<Polynomial, kMax + 1>;

// (a + b·s)^k for k = 0 … n, each from the one before: c_i ← a·c_i + b·c_{i−1}.
Powers linearPowers(double a, double b, int n) {
  Powers p;
  p[0].c[0] = 1;
  for (int k = 1; k <= n; ++k) {
    const Polynomial& q = p[size_t(k - 1)];
    Polynomial& r = p[size_t(k)];
    r.degree = k;
    r.c[0] = a * q.c[0];
    for (int i = 1; i <= k; ++i) r.c[size_t(i)] = a * q.c[size_t(i)] + b * q.c[size_t(i - 1)];
  }
  return p;
}

// x^n, with x^0 = 1 for every x.
double power(double x, int n) {
  double r = 1;
  for (int i = 0; i < n; ++i) r *= x;
  return r;
}

}  // namespace

AlgebraicSurface::AlgebraicSurface(std::vector<Monomial> terms, RootMethod method)
    : terms_(std::move(terms)), degree_(0), method_(method) {
  for (const Monomial& m : terms_) degree_ = std::max(degree_, m.x + m.y + m.z);
}

double AlgebraicSurface::value(const glm::dvec3& p) const {
  double v = 0;
  for (const Monomial& m : terms_) v += m.c * power(p.x, m.x) * power(p.y, m.y) * power(p.z, m.z);
  return v;
}

double AlgebraicSurface::magnitude(const glm::dvec3& q) const {
  double v = 0;
  for (const Monomial& m : terms_) v += std::abs(m.c) * power(q.x, m.x) * power(q.y, m.y) * power(q.z, m.z);
  return v;
}

glm::dvec3 AlgebraicSurface::gradient(const glm::dvec3& p) const {
  glm::dvec3 g(0);
  for (const Monomial& m : terms_) {
    const double px = power(p.x, m.x), py = power(p.y, m.y), pz = power(p.z, m.z);
    g.x += m.c * m.x * power(p.x, m.x - 1) * py * pz;
    g.y += m.c * m.y * px * power(p.y, m.y - 1) * pz;
    g.z += m.c * m.z * px * py * power(p.z, m.z - 1);
  }
  return g;
}

// The ray is written as c + s·u with u the unit direction and c its point nearest the origin, so that the
// coefficients are made from numbers no larger than the surface's own, and t = (t0 + s) / |d|. The terms'
// magnitudes at |c| + |s|·|u| bound the rounding of f's coefficients there, so a root s of f is uncertain by
// about γ·magnitude/|f′(s)|.
std::optional<double> AlgebraicSurface::firstHit(const glm::dvec3& o, const glm::dvec3& d, double lo, double hi,
                                                 double reach) const {
  const double len = glm::length(d);
  if (!(len > 0) || !std::isfinite(len) || degree_ == 0) return std::nullopt;
  const glm::dvec3 u = d / len;
  const double t0 = -glm::dot(o, u);
  const glm::dvec3 c = o + t0 * u;
  const double sLo = lo * len - t0;
  double a = sLo, b = hi * len - t0;
  if (std::isfinite(reach)) {
    const double h2 = reach * reach - glm::dot(c, c);
    if (h2 < 0) return std::nullopt;
    const double h = std::sqrt(h2) + 1e-9 * reach;
    a = std::max(a, -h);
    b = std::min(b, h);
  }
  const Powers x = linearPowers(c.x, u.x, degree_), y = linearPowers(c.y, u.y, degree_),
               z = linearPowers(c.z, u.z, degree_);
  Polynomial f;
  f.degree = degree_;
  for (const Monomial& t : terms_) {
    Polynomial term = x[size_t(t.x)];
    if (t.y > 0) term = times(term, y[size_t(t.y)]);
    if (t.z > 0) term = times(term, z[size_t(t.z)]);
    for (int i = 0; i <= term.degree; ++i) f.c[size_t(i)] += t.c * term.c[size_t(i)];
  }
  double roots[kMax];
  const int n = realRoots(f, a, b, roots, degree_, method_);
  const Polynomial slope = f.derivative();
  const double gamma = 8 * degree_ * std::numeric_limits<double>::epsilon();
  for (int i = 0; i < n; ++i) {
    const double s = roots[i], t = (t0 + s) / len;
    const double size = magnitude(glm::abs(c) + std::abs(s) * glm::abs(u));
    // t itself checked too: rounding t0 + s could bring it back to lo, and a CSG asking again from lo would loop.
    if (s - gamma * size / std::abs(slope(s)) > sLo && lo < t && t < hi) return t;
  }
  return std::nullopt;
}

template <class T>
std::optional<Hit<T>> Algebraic<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const glm::dvec3 o(ray.origin), d(ray.dir);
  const auto t = surface_.firstHit(o, d, double(range.min), double(range.max), reach_);
  if (!t) return std::nullopt;
  glm::dvec3 p = o + *t * d;
  const glm::dvec3 g = surface_.gradient(p);
  const double gg = glm::dot(g, g);
  if (!(gg > 0 && std::isfinite(gg))) return std::nullopt;  // a singular point, such as a cone's apex: no normal
  p -= surface_.value(p) / gg * g;  // one Newton step onto the surface (docs/reference/stability.md F4)
  Hit<T> hit;
  hit.t = T(*t);
  if (!range.surrounds(hit.t)) return std::nullopt;  // rounded to float onto an end of the range
  hit.point = Vec3<T>(p);
  hit.normal = Vec3<T>(g / std::sqrt(gg));
  hit.object = this;
  return hit;
}

template class Algebraic<float>;
template class Algebraic<double>;

}  // namespace rt
