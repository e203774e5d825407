#include "raytrace/geometry/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace rt {

Polynomial Polynomial::operator*(const Polynomial& b) const {
  Polynomial p;
  p.degree = degree + b.degree;
  for (int i = 0; i <= degree; ++i) {
    for (int j = 0; j <= b.degree; ++j) p.c[size_t(i + j)] += c[size_t(i)] * b.c[size_t(j)];
  }
  return p;
}

Polynomial Polynomial::derivative() const {
  Polynomial d;
  d.degree = std::max(degree - 1, 0);
  for (int i = 1; i <= degree; ++i) d.c[size_t(i - 1)] = i * c[size_t(i)];
  return d;
}

Polynomial times(const Polynomial& a, const Polynomial& b) {
  Polynomial p;
  p.degree = a.degree + b.degree;
  for (int i = 0; i <= a.degree; ++i) {
    for (int j = 0; j <= b.degree; ++j) p.c[size_t(i + j)] += a.c[size_t(i)] * b.c[size_t(j)];
  }
  return p;
}

Polynomial Polynomial::trimmed() const {
  Polynomial p = *this;
  while (p.degree > 0 && p.c[size_t(p.degree)] == 0) --p.degree;
  return p;
}

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr int kMax = Polynomial::kMaxDegree;

int sign(double x) { return (x > 0) - (x < 0); }

// Fujiwara's bound (1916): every root has |t| ≤ 2·max_k |c_{n−k} / c_n|^{1/k}, the constant term halved.
double rootBound(const Polynomial& p) {
  const int n = p.degree;
  double b = 0;
  for (int k = 1; k <= n; ++k) {
    const double ratio = std::abs(p.c[size_t(n - k)] / p.c[size_t(n)]) / (k == n ? 2 : 1);
    // The k-th root; the low ones without pow(), which the shapes' intersection tests would spend a third of
    // their time in (a bound needs no more than the 1.01 margin realRoots() gives it).
    const double root = k == 1 ? ratio : k == 2 ? std::sqrt(ratio) : k == 3 ? std::cbrt(ratio) : std::pow(ratio, 1.0 / k);
    b = std::max(b, root);
  }
  return 2 * b;
}

// The rounding error of Horner's rule at t is at most γ_2n·Σ|c_i|·|t|^i (Higham, Accuracy and Stability of
// Numerical Algorithms, §5.1).
double evaluationError(const Polynomial& p, double t) {
  double s = std::abs(p.c[size_t(p.degree)]);
  for (int i = p.degree - 1; i >= 0; --i) s = s * std::abs(t) + std::abs(p.c[size_t(i)]);
  return 2 * p.degree * kEps * s;
}

// The root in [a, b] of a p whose signs at a (fa = p(a)) and b differ: Newton's steps while they stay inside
// the shrinking bracket, halvings where they would leave it.
double refine(const Polynomial& p, double a, double b, double fa) {
  const Polynomial slope = p.derivative();
  double x = 0.5 * (a + b);
  for (int i = 0; i < 200; ++i) {
    const double f = p(x);
    if (f == 0) return x;
    if (sign(f) == sign(fa)) a = x;
    else b = x;
    double next = x - f / slope(x);
    if (!(next > a && next < b)) next = 0.5 * (a + b);
    if (std::abs(next - x) <= 2 * kEps * std::abs(x) || next <= a || next >= b) return next;
    x = next;
  }
  return x;
}

// Degree 1 and 2 in closed form; the quadratic as q = −(b + sign(b)·√Δ)/2, roots q/a and c/q, which subtracts
// no nearly equal numbers (Numerical Recipes §5.6).
int lowDegreeRoots(const Polynomial& p, double* roots) {
  if (p.degree == 1) {
    roots[0] = -p.c[0] / p.c[1];
    return 1;
  }
  const double a = p.c[2], b = p.c[1], c = p.c[0];
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return 0;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0) {  // b = c = 0: a·t²
    roots[0] = 0;
    return 1;
  }
  roots[0] = q / a;
  roots[1] = c / q;
  if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
  return roots[0] == roots[1] ? 1 : 2;
}

// Between consecutive roots of p' and the interval's ends p is monotone: a change of sign there is one root.
// A root of p' where p is zero within its rounding error is a multiple root.
int monotoneRoots(const Polynomial& p, double lo, double hi, double* roots) {
  if (p.degree <= 2) return lowDegreeRoots(p, roots);
  double knots[kMax];
  const int count = monotoneRoots(p.derivative(), lo, hi, knots);
  int n = 0;
  double a = lo, fa = p(lo);
  for (int k = 0; k <= count; ++k) {
    const double b = k < count ? knots[k] : hi, fb = p(b);
    if (!(a < b)) continue;  // a knot outside (lo, hi)
    if (sign(fa) * sign(fb) < 0) roots[n++] = refine(p, a, b, fa);
    else if (k < count && std::abs(fb) <= evaluationError(p, b)) roots[n++] = b;
    a = b;
    fa = fb;
  }
  return n;
}

// p's Sturm sequence (Sturm 1829): p, p', then each the negated remainder of the two before, until a
// remainder vanishes within rounding. Each is scaled to a largest coefficient of magnitude 1, which keeps its
// signs. The number of sign changes along it at a, less that at b, is the number of distinct roots in (a, b].
class SturmChain {
 public:
  explicit SturmChain(const Polynomial& p) {
    chain_[0] = normalized(p);
    chain_[1] = normalized(p.derivative());
    size_ = 2;
    while (chain_[size_ - 1].degree > 0) {
      Polynomial r = remainder(chain_[size_ - 2], chain_[size_ - 1]);
      if (largest(r) <= 1e-10) break;  // zero but for rounding: the last one is p's and p′'s common factor
      for (int i = 0; i <= r.degree; ++i) r.c[size_t(i)] = -r.c[size_t(i)];
      r = normalized(r);
      while (r.degree > 0 && std::abs(r.c[size_t(r.degree)]) <= 1e-12) --r.degree;
      chain_[size_++] = r;
    }
  }

  int changes(double x) const {
    int count = 0, last = 0;
    for (int i = 0; i < size_; ++i) {
      const int s = sign(chain_[size_t(i)](x));
      if (s == 0) continue;
      if (last != 0 && s != last) ++count;
      last = s;
    }
    return count;
  }

 private:
  static double largest(const Polynomial& p) {
    double m = 0;
    for (int i = 0; i <= p.degree; ++i) m = std::max(m, std::abs(p.c[size_t(i)]));
    return m;
  }
  static Polynomial normalized(Polynomial p) {
    const double m = largest(p);
    for (int i = 0; i <= p.degree; ++i) p.c[size_t(i)] /= m;
    return p;
  }
  static Polynomial remainder(Polynomial a, const Polynomial& b) {
    for (int k = a.degree - b.degree; k >= 0; --k) {
      const double q = a.c[size_t(k + b.degree)] / b.c[size_t(b.degree)];
      for (int i = 0; i < b.degree; ++i) a.c[size_t(k + i)] -= q * b.c[size_t(i)];
      a.c[size_t(k + b.degree)] = 0;
    }
    a.degree = b.degree - 1;
    return a;
  }

  std::array<Polynomial, kMax + 1> chain_;
  int size_;
};

// The roots in (a, b] found by halving it, the left half first, until each part holds one root: refined where
// p changes sign, else (a root of even multiplicity) halved down to the spacing of doubles.
struct Isolation {
  const Polynomial& p;
  const SturmChain& chain;
  double* roots;
  int most;
  int n = 0;

  void run(double a, double b, int va, int vb, int depth) {
    const int count = va - vb;
    if (count <= 0 || n >= most) return;
    if (count == 1) {
      const double fa = p(a), fb = p(b);
      if (fb == 0) {
        roots[n++] = b;
        return;
      }
      if (sign(fa) * sign(fb) < 0) {
        roots[n++] = refine(p, a, b, fa);
        return;
      }
    }
    // Sturm's theorem counts at points that are no root of p: a multiple root exactly at the middle would zero
    // the sequence's common factor along with p.
    double m = 0.5 * (a + b);
    for (int k = 0; k < 8 && p(m) == 0; ++k) m = 0.5 * (a + m);
    if (depth > 200 || b - a <= 4 * kEps * std::max(std::abs(a), std::abs(b))) {
      roots[n++] = m;  // a multiple root, or roots closer than doubles tell apart
      return;
    }
    const int vm = chain.changes(m);
    run(a, m, va, vm, depth + 1);
    run(m, b, vm, vb, depth + 1);
  }
};

}  // namespace

int realRoots(const Polynomial& poly, double lo, double hi, double* roots, int most, RootMethod method) {
  const Polynomial p = poly.trimmed();
  most = std::min(most, p.degree);
  if (most <= 0) return 0;
  const double bound = 1.01 * rootBound(p) + std::numeric_limits<double>::min();
  lo = std::max(lo, -bound);
  hi = std::min(hi, bound);
  if (!(lo < hi)) return 0;
  double found[kMax];
  int n;
  if (p.degree <= 2) {
    n = lowDegreeRoots(p, found);
  } else if (method == RootMethod::Auto && p.degree <= 4) {
    n = monotoneRoots(p, lo, hi, found);
  } else {
    const SturmChain chain(p);
    // The ends likewise, moved inward off a root of p, which the open interval leaves out anyway.
    for (int k = 0; k < 8 && p(lo) == 0; ++k) lo = std::nextafter(lo, hi);
    for (int k = 0; k < 8 && p(hi) == 0; ++k) hi = std::nextafter(hi, lo);
    Isolation isolation{p, chain, found, most};
    isolation.run(lo, hi, chain.changes(lo), chain.changes(hi), 0);
    n = isolation.n;
  }
  int kept = 0;
  for (int i = 0; i < n && kept < most; ++i) {
    if (lo < found[i] && found[i] < hi) roots[kept++] = found[i];
  }
  return kept;
}

}  // namespace rt
