// julia_fractal (POV-Ray 3.7 manual, "Julia Fractal"); the rules below were measured against POV-Ray 3.7 and
// are written out in docs/shapes.md, "julia_fractal".
#include "raytrace/shapes/julia_fractal.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace rt {

namespace {

using Complex = std::complex<double>;

// How close the bisection brings a crossing, and how far from a ray's start a crossing is ignored: a ray
// leaving a hit starts on its outer side within kTolerance and must not find it again.
constexpr double kTolerance = 1e-8, kSkip = 1e-6;

// Quaternion products (the manual's table: ij = k, jk = i, ki = j, ii = jj = kk = -1) of h with itself, written
// as h = a + v with v the imaginary part: h² = a² − |v|² + 2a·v, h³ = a³ − 3a|v|² + (3a² − |v|²)·v.
glm::dvec4 quaternionPower(const glm::dvec4& h, JuliaFunction f) {
  const double a = h.x, vv = h.y * h.y + h.z * h.z + h.w * h.w;
  const glm::dvec3 v(h.y, h.z, h.w);
  if (f == JuliaFunction::Sqr) return {a * a - vv, 2 * a * v};
  return {a * (a * a - 3 * vv), (3 * a * a - vv) * v};
}

// Hypercomplex numbers (the manual's table: ij = k, jk = −i, ki = −j, kk = 1) split into two independent complex
// numbers, u = (x − w) + i(y + z) and v = (x + w) + i(y − z): a function applies to each (Fractint's method).
Complex applied(Complex u, JuliaFunction f) {
  switch (f) {
    case JuliaFunction::Sqr: return u * u;
    case JuliaFunction::Cube: return u * u * u;
  }
  return u;
}
glm::dvec4 hypercomplexFunction(const glm::dvec4& h, JuliaFunction f) {
  const Complex u = applied({h.x - h.w, h.y + h.z}, f), v = applied({h.x + h.w, h.y - h.z}, f);
  return {(u.real() + v.real()) / 2, (u.imag() + v.imag()) / 2, (u.imag() - v.imag()) / 2, (v.real() - u.real()) / 2};
}

}  // namespace

// POV-Ray's bailout, measured: a quaternion orbit escapes past 1 + |p|, the radius outside which |h² + p| > |h|
// for sqr; a hypercomplex one past 4, the manual's radius.
double JuliaFractalParams::bailout() const {
  if (hypercomplex) return 16;
  const double r = 1 + glm::length(constant);
  return r * r;
}

void JuliaFractalDesc::describe(std::ostream& out) const {
  const JuliaFractalParams& p = *params;
  out << "- Parameter: " << fixed4(p.constant.x) << " " << fixed4(p.constant.y) << " " << fixed4(p.constant.z) << " "
      << fixed4(p.constant.w) << "\n- Algebra: " << (p.hypercomplex ? "hypercomplex" : "quaternion")
      << "\n- Function: " << (p.function == JuliaFunction::Sqr ? "sqr" : "cube") << "\n- Max iteration: " << p.maxIteration
      << "\n- Precision: " << fixed4(p.precision) << "\n";
}

template <class T>
JuliaFractal<T>::JuliaFractal(const JuliaFractalParams& d, const Material& material, int id)
    : Object<T>(material, id), d_(d), bailout_(d.bailout()), radius_(std::sqrt(d.bailout())) {}

// The 4-D point of the slice that projects to p: its fourth coordinate puts it on the slice's hyperplane
// n·h = distance.
template <class T> glm::dvec4 JuliaFractal<T>::point4(const glm::dvec3& p) const {
  const glm::dvec4& n = d_.slice;
  return {p, (d_.sliceDistance - n.x * p.x - n.y * p.y - n.z * p.z) / n.w};
}

template <class T> int JuliaFractal<T>::orbit(const glm::dvec3& p, double& step) const {
  glm::dvec4 h = point4(p);
  double derivative = 1;  // |dh_k/dh_0|, for the distance estimate
  const double power = d_.function == JuliaFunction::Sqr ? 2 : 3;
  for (int k = 0; k < d_.maxIteration; ++k) {
    const double norm2 = glm::dot(h, h);
    if (norm2 > bailout_) {
      step = d_.step();
      if (!d_.hypercomplex) {
        // The Julia sets' distance estimate |h| ln|h| / (2 |h'|) (the manual: used with the quaternions).
        const double norm = std::sqrt(norm2);
        step = std::max(step, 0.5 * norm * std::log(norm) / derivative);
      }
      return k;
    }
    derivative *= power * std::pow(norm2, (power - 1) / 2);
    h = (d_.hypercomplex ? hypercomplexFunction(h, d_.function) : quaternionPower(h, d_.function)) + d_.constant;
  }
  step = d_.step();
  return -1;
}

template <class T> double JuliaFractal<T>::normSquared(const glm::dvec3& p, int k) const {
  glm::dvec4 h = point4(p);
  for (int i = 0; i < k; ++i) {
    h = (d_.hypercomplex ? hypercomplexFunction(h, d_.function) : quaternionPower(h, d_.function)) + d_.constant;
  }
  return glm::dot(h, h);
}

template <class T> glm::dvec3 JuliaFractal<T>::gradient(const glm::dvec3& p, int k) const {
  const double e = 1e-7;
  return {normSquared(p + glm::dvec3(e, 0, 0), k) - normSquared(p - glm::dvec3(e, 0, 0), k),
          normSquared(p + glm::dvec3(0, e, 0), k) - normSquared(p - glm::dvec3(0, e, 0), k),
          normSquared(p + glm::dvec3(0, 0, e), k) - normSquared(p - glm::dvec3(0, 0, e), k)};
}

template <class T> std::optional<Aabb<T>> JuliaFractal<T>::bounds() const {
  return Aabb<T>{Vec3<T>(-radius_), Vec3<T>(radius_)};
}

// As POV-Ray: the march starts where the ray enters the bounding sphere, steps by the distance estimate (at
// least 1/precision) until a point's side differs from the start's, and bisects that step.
template <class T> std::optional<Hit<T>> JuliaFractal<T>::intersect(const Ray<T>& ray, Interval<T> range) const {
  const glm::dvec3 o(ray.origin), dir(ray.dir);
  const double a = glm::dot(dir, dir), b = glm::dot(o, dir), c = glm::dot(o, o) - bailout_;
  const double disc = b * b - a * c;
  if (!(disc >= 0)) return std::nullopt;
  const double root = std::sqrt(disc), speed = std::sqrt(a);
  const double lo = std::max((-b - root) / a, double(range.min) + kSkip / speed);
  const double hi = std::min((-b + root) / a, double(range.max));
  if (!(lo < hi)) return std::nullopt;

  double t = lo, step;
  const bool startInside = orbit(o + t * dir, step) < 0;
  for (;;) {
    const double next = t + step / speed;
    if (next > hi) return std::nullopt;
    if ((orbit(o + next * dir, step) < 0) != startInside) {
      // Bisect [t, next] down to kTolerance, `in` and `out` its ends inside and outside.
      double in = startInside ? t : next, out = startInside ? next : t;
      while (std::abs(out - in) * speed > kTolerance) {
        const double m = (in + out) / 2;
        (escape(o + m * dir) < 0 ? in : out) = m;
      }
      const glm::dvec3 p = o + out * dir;
      // POV-Ray's normal, measured: the gradient of |h_n|², n = max_iteration, by central differences; where
      // that term overflows (the orbit escaped well before it), the gradient of the term that escapes.
      glm::dvec3 g = gradient(p, d_.maxIteration);
      if (!std::isfinite(glm::dot(g, g))) g = gradient(p, escape(p));
      Hit<T> h;
      h.t = T(out);
      h.point = Vec3<T>(p);
      h.normal = Vec3<T>(glm::length(g) > 0 ? glm::normalize(g) : -glm::normalize(dir));
      h.object = this;
      return h;
    }
    t = next;
  }
}

template class JuliaFractal<float>;
template class JuliaFractal<double>;

}  // namespace rt
