// Polynomials in one variable up to degree 7 and their real roots: what a ray meets on the polynomial shapes
// (torus, quadric, cubic, quartic, poly).
#pragma once

#include <array>
#include <cstddef>

namespace rt {

struct Polynomial {
  static constexpr int kMaxDegree = 7;
  std::array<double, kMaxDegree + 1> c{};  // c[i] multiplies t^i
  int degree = 0;

  double operator()(double t) const {
    double v = c[size_t(degree)];
    for (int i = degree - 1; i >= 0; --i) v = v * t + c[size_t(i)];
    return v;
  }
  Polynomial derivative() const;
  // The product, whose degree is the sum of the two (at most kMaxDegree: the caller's to keep).
  Polynomial operator*(const Polynomial& b) const;
  // The degree lowered past leading coefficients that are zero.
  Polynomial trimmed() const;
};

// The product a·b; the degrees must add up to at most kMaxDegree.
Polynomial times(const Polynomial& a, const Polynomial& b);

// How the roots are found. Auto: closed forms up to degree 2, the derivative's roots splitting the line into
// monotone pieces for degrees 3 and 4, Sturm sequences above; Sturm: Sturm sequences for every degree above 2
// (POV-Ray's `sturm`).
enum class RootMethod { Auto, Sturm };

// The distinct real roots of p in the open interval (lo, hi), ascending: the `most` smallest of them. A multiple
// root is reported once (or as a cluster of nearby roots where rounding splits it). Returns how many were
// written; `roots` has room for `most`. A polynomial that is zero everywhere has no roots here.
int realRoots(const Polynomial& p, double lo, double hi, double* roots, int most, RootMethod method = RootMethod::Auto);

}  // namespace rt
