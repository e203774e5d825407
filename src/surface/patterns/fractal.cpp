// mandel, julia and magnet 1 / 2 (POV-Ray 3.7 manual, "Fractal Pattern"): the point in x and y iterated as a
// complex number, z ← z^exponent + c for mandel (z and c start at the point) and julia (c is the constant), and
// fractint's magnet maps for magnet (mandel form: z starts at 0, c is the point). The value is taken where the
// orbit leaves (|z|² > 4; magnet: |z|² > 10000 or |z − 1|² < 10⁻⁴) by the exterior type, else by the interior
// type after all the iterations. What was measured on POV-Ray's values beyond the manual: the iteration count
// starts at 0 after the first step; interior 1's orbit includes the starting point for mandel and julia but not
// for magnet; interior 6 is x² + factor·y² of the last point (docs/povray-noise.md).
#include <algorithm>
#include <cmath>
#include <iterator>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

using Set = FractalArgs::Set;

// Complex arithmetic written out, as the manual's formulas read (std::complex's guards against infinities cost
// a call per product).
struct Complex {
  double re = 0, im = 0;
};
Complex operator+(Complex a, Complex b) { return {a.re + b.re, a.im + b.im}; }
Complex operator+(Complex a, double b) { return {a.re + b, a.im}; }
Complex operator*(Complex a, Complex b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
Complex operator*(double a, Complex b) { return {a * b.re, a * b.im}; }
Complex operator/(Complex a, Complex b) {
  const double d = b.re * b.re + b.im * b.im;
  return {(a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d};
}
double norm(Complex z) { return z.re * z.re + z.im * z.im; }

class Fractal final : public Pattern {
 public:
  explicit Fractal(const FractalArgs& a) : a_(a) {}

  double value(const glm::dvec3& p) const override {
    const Complex point{p.x, p.y};
    const bool magnet = a_.set != Set::Mandel && a_.set != Set::Julia;
    const bool julia = a_.set == Set::Julia || a_.set == Set::Magnet1Julia || a_.set == Set::Magnet2Julia;
    const Complex c = julia ? Complex{a_.constant.x, a_.constant.y} : point;
    Complex z = magnet && !julia ? Complex{} : point;
    double smallest = magnet ? HUGE_VAL : norm(z);
    for (int n = 0; n < a_.iterations; ++n) {
      z = magnet ? magnetStep(z, c) : power(z) + c;
      const double r2 = norm(z);
      const bool out = magnet ? r2 > 10000 || norm(z + -1.0) < 1e-4 : r2 > 4;
      if (out) return a_.exteriorType == 1 ? double(n) / a_.iterations : lastPoint(a_.exteriorType, a_.exteriorFactor, z);
      smallest = std::min(smallest, r2);
    }
    if (a_.interiorType == 1) return std::sqrt(smallest) * a_.interiorFactor;
    if (a_.interiorType == 6) return z.re * z.re + z.im * z.im * a_.interiorFactor;
    return lastPoint(a_.interiorType, a_.interiorFactor, z);
  }

 private:
  Complex power(const Complex& z) const {
    Complex r = z;
    for (int k = 1; k < a_.exponent; ++k) r = r * z;
    return r;
  }

  // Magnet 1: ((z² + c − 1) / (2z + c − 2))²; magnet 2: ((z³ + 3(c − 1)z + (c − 1)(c − 2)) /
  // (3z² + 3(c − 2)z + (c − 1)(c − 2) + 1))².
  Complex magnetStep(const Complex& z, const Complex& c) const {
    Complex q;
    if (a_.set == Set::Magnet1Mandel || a_.set == Set::Magnet1Julia) {
      q = (z * z + c + -1.0) / (2.0 * z + c + -2.0);
    } else {
      const Complex c1 = c + -1.0, c2 = c + -2.0;
      q = (z * z * z + 3.0 * (c1 * z) + c1 * c2) / (3.0 * (z * z) + 3.0 * (c2 * z) + c1 * c2 + 1.0);
    }
    return q * q;
  }

  // The types read from the orbit's last point: 0 the factor alone, 2 and 3 its parts, 4 and 5 their squares,
  // 6 its length; each times the factor.
  static double lastPoint(int type, double factor, const Complex& z) {
    switch (type) {
      case 2: return z.re * factor;
      case 3: return z.im * factor;
      case 4: return z.re * z.re * factor;
      case 5: return z.im * z.im * factor;
      case 6: return std::sqrt(norm(z)) * factor;
      default: return factor;
    }
  }

  FractalArgs a_;
};

}  // namespace

// Its own colour map: mandel's: black, then cyan, yellow, magenta and back to cyan.
constexpr ColourStop kMandelStops[] = {
    {0, Color(0)}, {0.001, Color(0)}, {0.001, Color(0, 1, 1)}, {0.012, Color(1, 1, 0)}, {0.015, Color(1, 0, 1)}, {0.1, Color(0, 1, 1)}};
const DefaultMap kMandelMap{kMandelStops, std::size(kMandelStops)};

std::unique_ptr<Pattern> makeFractal(const PatternArgs& a) { return std::make_unique<Fractal>(a.fractal); }

}  // namespace rt
