// POV-Ray's splines (manual, "Spline"). Beyond the points the value stays at the end points (cubic: at the
// second and the next-to-last, its first and last points only shaping the curve). The curves, fitted to POV-Ray's
// values (tests/parse/povray/test_spline.cpp): linear between neighbours; quadratic, on each interval the
// parabola through its two points and the one before (the first interval: the one after); cubic, Hermite's
// cubic whose slope at each point is the mean of the slopes of the chords on either side; natural, the cubic
// spline with no curvature at its ends.
#include "raytrace/parse/povray/spline.hpp"

#include <algorithm>
#include <cstddef>

#include "raytrace/util/error.hpp"

namespace rt::povray {

namespace {

using Point = std::array<double, 5>;

Point mix(const Point& a, double wa, const Point& b, double wb) {
  Point r{};
  for (size_t i = 0; i < 5; ++i) r[i] = wa * a[i] + wb * b[i];
  return r;
}

// The interval [t_k, t_k+1] holding t, k within [first, last − 1].
size_t interval(const std::vector<double>& t, double at, size_t first, size_t last) {
  size_t k = first;
  while (k + 1 < last && t[k + 1] <= at) ++k;
  return k;
}

Point linear(const SplinePoints& s, double at) {
  const size_t k = interval(s.t, at, 0, s.t.size() - 1);
  const double u = (at - s.t[k]) / (s.t[k + 1] - s.t[k]);
  return mix(s.p[k], 1 - u, s.p[k + 1], u);
}

// Lagrange's parabola through points a, b, c, at `at`.
Point quadratic(const SplinePoints& s, double at) {
  const size_t k = interval(s.t, at, 0, s.t.size() - 1);
  const size_t a = k == 0 ? 0 : k - 1, b = a + 1, c = a + 2;
  const double ta = s.t[a], tb = s.t[b], tc = s.t[c];
  const double la = (at - tb) * (at - tc) / ((ta - tb) * (ta - tc));
  const double lb = (at - ta) * (at - tc) / ((tb - ta) * (tb - tc));
  const double lc = (at - ta) * (at - tb) / ((tc - ta) * (tc - tb));
  return mix(mix(s.p[a], la, s.p[b], lb), 1, s.p[c], lc);
}

Point cubic(const SplinePoints& s, double at) {
  const size_t n = s.t.size();
  at = std::clamp(at, s.t[1], s.t[n - 2]);
  const size_t k = interval(s.t, at, 1, n - 2);
  const double h = s.t[k + 1] - s.t[k], u = (at - s.t[k]) / h;
  const auto slope = [&](size_t i, size_t j) { return mix(s.p[j], 1 / (s.t[j] - s.t[i]), s.p[i], -1 / (s.t[j] - s.t[i])); };
  const Point before = slope(k - 1, k), across = slope(k, k + 1), after = slope(k + 1, k + 2);
  const Point m0 = mix(before, h / 2, across, h / 2), m1 = mix(across, h / 2, after, h / 2);
  const double u2 = u * u, u3 = u2 * u;
  return mix(mix(s.p[k], 2 * u3 - 3 * u2 + 1, m0, u3 - 2 * u2 + u), 1,
             mix(s.p[k + 1], 3 * u2 - 2 * u3, m1, u3 - u2), 1);
}

// The second derivatives at the points (zero at the ends), by the tridiagonal system of the cubic spline.
Point natural(const SplinePoints& s, double at) {
  const size_t n = s.t.size();
  std::vector<Point> second(n, Point{}), rhs(n, Point{});
  std::vector<double> diag(n, 1), upper(n, 0), lower(n, 0);
  for (size_t i = 1; i + 1 < n; ++i) {
    const double h0 = s.t[i] - s.t[i - 1], h1 = s.t[i + 1] - s.t[i];
    lower[i] = h0 / 6;
    diag[i] = (h0 + h1) / 3;
    upper[i] = h1 / 6;
    for (size_t c = 0; c < 5; ++c) rhs[i][c] = (s.p[i + 1][c] - s.p[i][c]) / h1 - (s.p[i][c] - s.p[i - 1][c]) / h0;
  }
  // Thomas's algorithm: eliminate below the diagonal, then substitute back.
  for (size_t i = 1; i < n; ++i) {
    const double w = lower[i] / diag[i - 1];
    diag[i] -= w * upper[i - 1];
    for (size_t c = 0; c < 5; ++c) rhs[i][c] -= w * rhs[i - 1][c];
  }
  for (size_t i = n; i-- > 0;) {
    for (size_t c = 0; c < 5; ++c) {
      second[i][c] = (rhs[i][c] - (i + 1 < n ? upper[i] * second[i + 1][c] : 0)) / diag[i];
    }
  }
  const size_t k = interval(s.t, at, 0, n - 1);
  const double h = s.t[k + 1] - s.t[k], a = (s.t[k + 1] - at) / h, b = 1 - a;
  Point r{};
  for (size_t c = 0; c < 5; ++c) {
    r[c] = a * s.p[k][c] + b * s.p[k + 1][c] +
           ((a * a * a - a) * second[k][c] + (b * b * b - b) * second[k + 1][c]) * h * h / 6;
  }
  return r;
}

}  // namespace

std::optional<SplineKind> splineKindNamed(std::string_view word) {
  if (word == "linear_spline") return SplineKind::Linear;
  if (word == "quadratic_spline") return SplineKind::Quadratic;
  if (word == "cubic_spline") return SplineKind::Cubic;
  if (word == "natural_spline") return SplineKind::Natural;
  return std::nullopt;
}

SplinePoints splinePoints(const Node& spline) {
  SplinePoints s;
  for (size_t i = 0; i < spline.items.size(); ++i) {
    const Item& it = spline.items[i];
    if (i == 0 && it.kind == Item::Kind::Node && it.node->keyword == "spline") {
      s = splinePoints(*it.node);
      continue;
    }
    if (it.kind == Item::Kind::Keyword) {
      const std::optional<SplineKind> kind = splineKindNamed(it.word);
      if (!kind) throw ParseError(it.loc, "'" + std::string(it.word) + "' is not a spline type");
      s.kind = *kind;
      continue;
    }
    if (it.kind != Item::Kind::Value || it.value.type != Value::Type::Float) {
      throw ParseError(it.loc, "a spline needs a parameter value here, then a point");
    }
    if (i + 1 >= spline.items.size() || spline.items[i + 1].kind != Item::Kind::Value ||
        !spline.items[i + 1].value.numeric()) {
      throw ParseError(it.loc, "a spline's parameter value needs a point after it");
    }
    const double t = it.value.v[0];
    const Value& point = spline.items[++i].value;
    const int size = point.type == Value::Type::Float ? 1 : point.size;
    Point p{};
    for (int c = 0; c < size; ++c) p[size_t(c)] = point.v[size_t(c)];
    s.size = std::max(s.size, size);
    const auto at = std::lower_bound(s.t.begin(), s.t.end(), t);
    const size_t k = size_t(at - s.t.begin());
    if (at != s.t.end() && *at == t) {
      s.p[k] = p;
    } else {
      s.t.insert(at, t);
      s.p.insert(s.p.begin() + std::ptrdiff_t(k), p);
    }
  }
  if (s.t.empty()) throw ParseError(spline.loc, "the spline has no points");
  return s;
}

std::array<double, 5> splineAt(const SplinePoints& s, double t, SplineKind kind) {
  const size_t n = s.t.size();
  if (kind == SplineKind::Cubic) return n >= 4 ? cubic(s, t) : s.p[std::min<size_t>(1, n - 1)];  // as POV-Ray
  if (n == 1 || t <= s.t.front()) return s.p.front();
  if (t >= s.t.back()) return s.p.back();
  if (kind == SplineKind::Linear || n == 2) return linear(s, t);
  if (kind == SplineKind::Quadratic) return quadratic(s, t);
  return natural(s, t);
}

}  // namespace rt::povray
