// Ray-sphere intersection with both formulas (textbook and robust) in both precisions: hits, misses,
// tangents, rays from inside and from the surface, the open interval, and a seeded sweep where the two agree.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "raytrace/shapes/sphere.hpp"

using rt::SphereMethod;

namespace {

template <class T> rt::Sphere<T> sphere(rt::Vec3<T> c, T r, SphereMethod m) {
  return rt::Sphere<T>(c, r, m, rt::Material{}, 1);
}

}  // namespace

#define BOTH_FORMULAS                                                                  \
  using T = TestType;                                                                  \
  const SphereMethod method = GENERATE(SphereMethod::Textbook, SphereMethod::Robust); \
  CAPTURE(method == SphereMethod::Robust)

TEMPLATE_TEST_CASE("sphere: a hit from outside takes the near root", "", float, double) {
  BOTH_FORMULAS;
  const auto s = sphere<T>({0, 0, 0}, 2, method);
  const auto hit = s.intersect({{0, 0, 14}, {0, 0, -1}}, {});
  REQUIRE(hit);
  CHECK(hit->t == T(12));
  CHECK(hit->point == rt::Vec3<T>(0, 0, 2));
  CHECK(hit->normal == rt::Vec3<T>(0, 0, 1));
  CHECK(hit->object == &s);
  CHECK(hit->frontFace(rt::Vec3<T>(0, 0, -1)));
}

TEMPLATE_TEST_CASE("sphere: the course's firsthit on simple.pov (p1 T = 12.0001)", "", float, double) {
  BOTH_FORMULAS;
  const rt::Vec3<T> dir(T(0.0010416629322267603), T(0.0010416655363907124), T(-0.9999989149350342));
  const auto hit = sphere<T>({0, 0, 0}, 2, method).intersect({{0, 0, 14}, dir}, {});
  REQUIRE(hit);
  // Exact: b = f·d, t = −b − √(b² − |f|² + r²) with |f| = 14.
  const double b = 14 * -0.9999989149350342;
  CHECK(double(hit->t) == Approx(-b - std::sqrt(b * b - 196 + 4)).epsilon(1e-6));
  CHECK(double(hit->t) == Approx(12.00009).epsilon(1e-6));
}

TEMPLATE_TEST_CASE("sphere: misses, and spheres behind the ray", "", float, double) {
  BOTH_FORMULAS;
  const auto s = sphere<T>({0, 0, 0}, 2, method);
  CHECK_FALSE(s.intersect({{3, 0, 14}, {0, 0, -1}}, {}));
  CHECK_FALSE(s.intersect({{0, 0, 14}, {0, 0, 1}}, {}));
  CHECK_FALSE(s.intersect({{0, 0, 14}, glm::normalize(rt::Vec3<T>(1, 0, -1))}, {}));
}

TEMPLATE_TEST_CASE("sphere: tangent rays touch at one point; just outside they miss", "", float, double) {
  BOTH_FORMULAS;
  const auto s = sphere<T>({0, 0, 0}, 2, method);
  const auto touch = s.intersect({{2, 0, 10}, {0, 0, -1}}, {});
  REQUIRE(touch);
  CHECK(touch->t == T(10));
  CHECK(touch->point == rt::Vec3<T>(2, 0, 0));
  CHECK(touch->normal == rt::Vec3<T>(1, 0, 0));
  CHECK_FALSE(s.intersect({{T(2.001), 0, 10}, {0, 0, -1}}, {}));
}

TEMPLATE_TEST_CASE("sphere: from inside, the far root, with the normal still outward", "", float, double) {
  BOTH_FORMULAS;
  const auto s = sphere<T>({1, 1, 1}, 2, method);
  const auto hit = s.intersect({{1, 1, 1}, {1, 0, 0}}, {});
  REQUIRE(hit);
  CHECK(hit->t == T(2));
  CHECK(hit->point == rt::Vec3<T>(3, 1, 1));
  CHECK(hit->normal == rt::Vec3<T>(1, 0, 0));
  CHECK_FALSE(hit->frontFace(rt::Vec3<T>(1, 0, 0)));
}

TEMPLATE_TEST_CASE("sphere: the interval is open at both ends", "", float, double) {
  BOTH_FORMULAS;
  const auto s = sphere<T>({0, 0, 0}, 2, method);
  const rt::Ray<T> ray{{0, 0, 14}, {0, 0, -1}};  // roots 12 and 16
  CHECK(s.intersect(ray, {T(0), T(16)})->t == T(12));
  CHECK_FALSE(s.intersect(ray, {T(0), T(12)}));
  const auto far = s.intersect(ray, {T(12), T(100)});
  REQUIRE(far);
  CHECK(far->t == T(16));
  CHECK(far->normal == rt::Vec3<T>(0, 0, -1));
  CHECK_FALSE(s.intersect(ray, {T(12), T(16)}));
  CHECK_FALSE(s.intersect(ray, {T(16), T(100)}));
}

TEMPLATE_TEST_CASE("sphere: a ray starting on the surface never re-hits its own origin", "", float, double) {
  BOTH_FORMULAS;
  const auto s = sphere<T>({0, 0, 0}, 2, method);
  const auto through = s.intersect({{0, 0, 2}, {0, 0, -1}}, {});  // roots 0 and 4
  REQUIRE(through);
  CHECK(through->t == T(4));
  CHECK_FALSE(s.intersect({{0, 0, 2}, {0, 0, 1}}, {}));   // roots −4 and 0
  CHECK_FALSE(s.intersect({{0, 0, 2}, {1, 0, 0}}, {}));   // tangent at the origin
}

TEMPLATE_TEST_CASE("sphere: unnormalized directions keep t in the ray's own units", "", float, double) {
  BOTH_FORMULAS;
  const auto hit = sphere<T>({0, 0, 0}, 2, method).intersect({{0, 0, 14}, {0, 0, -2}}, {});
  REQUIRE(hit);
  CHECK(hit->t == T(6));
  CHECK(hit->point == rt::Vec3<T>(0, 0, 2));
}

TEMPLATE_TEST_CASE("sphere: bounds", "", float, double) {
  BOTH_FORMULAS;
  const auto box = sphere<T>({1, -2, 3}, T(0.5), method).bounds();
  REQUIRE(box);
  CHECK(box->min == rt::Vec3<T>(T(0.5), T(-2.5), T(2.5)));
  CHECK(box->max == rt::Vec3<T>(T(1.5), T(-1.5), T(3.5)));
}

TEST_CASE("sphere: both formulas agree with the exact root on random rays (seeded)") {
  const unsigned seed = 473;
  CAPTURE(seed);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 c(5 * u(rng), 5 * u(rng), 5 * u(rng));
    const double r = 0.5 + std::abs(u(rng));
    const glm::dvec3 o(10 * u(rng), 10 * u(rng), 10 * u(rng));
    const glm::dvec3 d = glm::normalize(c + glm::dvec3(2 * u(rng), 2 * u(rng), 2 * u(rng)) - o);
    CAPTURE(i);
    // Reference in long double from the plain quadratic.
    const long double b = (long double)glm::dot(o - c, d);
    const long double disc = b * b - ((long double)glm::dot(o - c, o - c) - (long double)r * r);
    const auto textbook = sphere<double>(c, r, SphereMethod::Textbook).intersect({o, d}, {});
    const auto robust = sphere<double>(c, r, SphereMethod::Robust).intersect({o, d}, {});
    const auto robustF = sphere<float>(c, float(r), SphereMethod::Robust).intersect({o, d}, {});
    if (disc < -1e-6L) {
      CHECK_FALSE(textbook);
      CHECK_FALSE(robust);
    }
    if (disc < 1e-6L) continue;  // too close to tangent to say which side wins
    const long double t0 = -b - std::sqrt(disc), t1 = -b + std::sqrt(disc);
    const long double exact = t0 > 1e-6L ? t0 : t1;
    if (exact <= 1e-6L) {
      CHECK_FALSE(textbook);
      CHECK_FALSE(robust);
      continue;
    }
    ++hits;
    REQUIRE(textbook);
    REQUIRE(robust);
    REQUIRE(robustF);
    CHECK(textbook->t == Approx(double(exact)).epsilon(1e-9));
    CHECK(robust->t == Approx(double(exact)).epsilon(1e-9));
    CHECK(double(robustF->t) == Approx(double(exact)).epsilon(1e-4));
    CHECK(glm::length(robust->point - c) == Approx(r).epsilon(1e-12));
  }
  CHECK(hits > 400);  // the sweep really exercises hits (482 with this seed)
}

TEST_CASE("sphere: far from a small sphere, the robust test stays exact in float where the textbook one fails") {
  // Radius 1 at distance 1e4 (precision budget R = 1e4, docs/reference/stability.md F1): t = 9999 exactly.
  const rt::Ray<float> ray{{0, 0, 1e4f}, {0, 0, -1}};
  const auto robust = sphere<float>({0, 0, 0}, 1, SphereMethod::Robust).intersect(ray, {});
  REQUIRE(robust);
  CHECK(robust->t == Approx(9999).margin(2e-3));
  // The textbook discriminant 4·1e8 − 4·(1e8 − 1) cancels to 0 in float: t comes out as 1e4, off by a whole radius.
  const auto textbook = sphere<float>({0, 0, 0}, 1, SphereMethod::Textbook).intersect(ray, {});
  CHECK((!textbook || std::abs(textbook->t - 9999.0f) > 0.5f));
}

TEMPLATE_TEST_CASE("sphere: the shadow test of a packet occludes exactly the rays intersect() hits", "", float, double) {
  BOTH_FORMULAS;
  constexpr int kRays = 32;
  const auto s = sphere<T>({1, -2, 0.5}, T(1.5), method);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(-4, 4), unit(0, 1);
  int occluded = 0;
  for (int round = 0; round < 300; ++round) {
    CAPTURE(round);
    rt::Ray<T> rays[kRays];
    rt::Interval<T> ranges[kRays];
    for (int i = 0; i < kRays; ++i) {
      // Aimed near the sphere, from inside it or outside, with segments that end before, inside or past it.
      const glm::dvec3 o(pos(rng), pos(rng), pos(rng));
      const glm::dvec3 target = glm::dvec3(1, -2, 0.5) + 0.6 * glm::dvec3(pos(rng), pos(rng), pos(rng));
      rays[i] = {rt::Vec3<T>(o), rt::Vec3<T>(glm::normalize(target - o))};
      ranges[i] = {T(unit(rng) < 0.2 ? unit(rng) : 0), T(unit(rng) < 0.7 ? 8 * unit(rng) : 1e30)};
    }
    const uint32_t open = uint32_t(rng());
    const uint32_t mine = s.occludes(rays, ranges, open);
    CHECK(mine == s.rt::Object<T>::occludes(rays, ranges, open));  // intersect() ray by ray
    occluded += __builtin_popcount(mine);
  }
  CHECK(occluded > 1000);  // the sweep really has rays of both kinds
}
