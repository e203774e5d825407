// The real roots of polynomials up to degree 7, by both methods, against polynomials built from their roots.
#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "raytrace/geometry/polynomial.hpp"

using namespace rt;

namespace {

// lead · Π (t − r) · Π (t² + b·t + c) for the pairs (b, c), which have no real roots when b² < 4c.
Polynomial build(double lead, const std::vector<double>& roots, const std::vector<std::pair<double, double>>& pairs = {}) {
  Polynomial p;
  p.c[0] = lead;
  for (const double r : roots) {
    Polynomial f;
    f.degree = 1;
    f.c[0] = -r;
    f.c[1] = 1;
    p = times(p, f);
  }
  for (const auto& [b, c] : pairs) {
    Polynomial f;
    f.degree = 2;
    f.c[0] = c;
    f.c[1] = b;
    f.c[2] = 1;
    p = times(p, f);
  }
  return p;
}

std::vector<double> solve(const Polynomial& p, RootMethod method, double lo = -1e9, double hi = 1e9, int most = 7) {
  double roots[Polynomial::kMaxDegree];
  const int n = realRoots(p, lo, hi, roots, most, method);
  return std::vector<double>(roots, roots + n);
}

// Each expected root (listed once however multiple) has found roots within `tolerance` (relative above 1), and
// every found root lies so near one of them; the found roots ascend.
void checkRoots(const std::vector<double>& found, std::vector<double> expected, double tolerance) {
  CAPTURE(found, expected);
  std::sort(expected.begin(), expected.end());
  expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
  CHECK(std::is_sorted(found.begin(), found.end()));
  const auto near = [&](double a, double b) { return std::abs(a - b) <= tolerance * std::max(1.0, std::abs(b)); };
  for (const double e : expected) CHECK(std::any_of(found.begin(), found.end(), [&](double f) { return near(f, e); }));
  for (const double f : found) CHECK(std::any_of(expected.begin(), expected.end(), [&](double e) { return near(f, e); }));
}

const RootMethod kMethods[] = {RootMethod::Auto, RootMethod::Sturm};

}  // namespace

TEST_CASE("simple roots of every degree are found to full precision", "[polynomial]") {
  const std::vector<double> all = {-3.5, -1, 0.25, 1, 2, 4.75, 9};
  for (const RootMethod method : kMethods) {
    for (size_t degree = 1; degree <= all.size(); ++degree) {
      const std::vector<double> roots(all.begin(), all.begin() + long(degree));
      CAPTURE(degree, int(method));
      const std::vector<double> found = solve(build(-2.5, roots), method);
      REQUIRE(found.size() == degree);
      checkRoots(found, roots, 1e-12);
    }
  }
}

TEST_CASE("a multiple root is reported once, or as a tight cluster", "[polynomial]") {
  for (const RootMethod method : kMethods) {
    CAPTURE(int(method));
    CHECK(solve(build(1, {1, 1}), method) == std::vector<double>{1});
    checkRoots(solve(build(1, {1, 1, 2}), method), {1, 2}, 1e-7);
    checkRoots(solve(build(3, {2, 2, -1, -1}), method), {2, -1}, 1e-7);
    checkRoots(solve(build(1, {-0.5, -0.5, -0.5}), method), {-0.5}, 1e-4);
    checkRoots(solve(build(1, {0.5, 0.5, 0.5, 0.5}), method), {0.5}, 1e-3);
    checkRoots(solve(build(1, {1, 1, 3, 3, 5, 6}), method), {1, 3, 5, 6}, 1e-6);
    checkRoots(solve(build(1, {0, 0, 0, 2, 2, -1, 4}), method), {0, 2, -1, 4}, 1e-4);
  }
}

TEST_CASE("widely spread roots are each found to their own precision", "[polynomial]") {
  for (const RootMethod method : kMethods) {
    CAPTURE(int(method));
    checkRoots(solve(build(1, {1e-3, 1, 1e3}), method), {1e-3, 1, 1e3}, 1e-10);
    checkRoots(solve(build(1e-4, {-1e4, 1e-2, 0.5, 1e4}), method), {-1e4, 1e-2, 0.5, 1e4}, 1e-10);
    checkRoots(solve(build(7, {-300, -1e-3, 2e-2, 1, 40, 2e3, 1e5}), method),
               {-300, -1e-3, 2e-2, 1, 40, 2e3, 1e5}, 1e-8);
  }
}

TEST_CASE("polynomials without real roots have none", "[polynomial]") {
  for (const RootMethod method : kMethods) {
    CAPTURE(int(method));
    CHECK(solve(build(1, {}, {{0, 1}}), method).empty());
    CHECK(solve(build(-2, {}, {{0, 1}, {1, 2}}), method).empty());
    CHECK(solve(build(1, {}, {{0, 1}, {0, 1}, {0, 1}}), method).empty());
    CHECK(solve(build(1, {5}, {{1, 1}, {-4, 5}}), method) == std::vector<double>{5});
    Polynomial constant;
    constant.c[0] = 3;
    CHECK(solve(constant, method).empty());
    CHECK(solve(Polynomial{}, method).empty());  // zero everywhere: no root to report
  }
}

TEST_CASE("only the roots inside the open interval, the smallest first", "[polynomial]") {
  const Polynomial p = build(1, {-2, -1, 0.5, 1, 3});
  for (const RootMethod method : kMethods) {
    CAPTURE(int(method));
    checkRoots(solve(p, method, -1, 3), {0.5, 1}, 1e-12);
    checkRoots(solve(p, method, 0, 1e300), {0.5, 1, 3}, 1e-12);
    checkRoots(solve(p, method, -1e9, 1e9, 2), {-2, -1}, 1e-12);
    CHECK(solve(p, method, 1.5, 2.5).empty());
    CHECK(solve(p, method, 2, 1).empty());
  }
  // A leading coefficient of zero lowers the degree.
  Polynomial q = build(1, {2, 4});
  q.degree = 5;
  checkRoots(solve(q, RootMethod::Auto), {2, 4}, 1e-12);
}

TEST_CASE("seeded sweep: random real roots and root-free factors, every degree, both methods", "[polynomial]") {
  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int trial = 0; trial < 3000; ++trial) {
    const int degree = 3 + trial % 5;
    const int pairs = int(rng() % unsigned(degree / 2 + 1));
    std::vector<double> roots;
    while (int(roots.size()) < degree - 2 * pairs) {
      const double r = 10 * unit(rng) * std::pow(10.0, 2 * unit(rng));
      // Apart by at least 1 % of their size: closer roots are a cluster, tested above.
      if (std::none_of(roots.begin(), roots.end(), [&](double s) { return std::abs(s - r) < 0.01 * std::max(1.0, std::abs(r)); })) {
        roots.push_back(r);
      }
    }
    std::vector<std::pair<double, double>> quadratics;
    for (int k = 0; k < pairs; ++k) {
      const double centre = 5 * unit(rng), spread = 0.1 + 3 * std::abs(unit(rng));
      quadratics.push_back({-2 * centre, centre * centre + spread * spread});
    }
    const double lead = std::pow(10.0, 3 * unit(rng)) * (unit(rng) < 0 ? -1 : 1);
    const Polynomial p = build(lead, roots, quadratics);
    for (const RootMethod method : kMethods) {
      CAPTURE(trial, degree, int(method), lead, pairs);
      const std::vector<double> found = solve(p, method, -1e6, 1e6);
      CHECK(found.size() == roots.size());
      checkRoots(found, roots, 1e-7);
    }
  }
}
