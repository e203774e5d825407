// cubic, quartic and poly: POV-Ray's term order, and rays against surfaces whose hits are known.
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <catch2/catch.hpp>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/shapes/poly.hpp"
#include "raytrace/shapes/torus.hpp"
#include "parse_message.hpp"
#include "shape_oracle.hpp"

using namespace rt;

namespace {

const Material kMaterial{};
const ObjectBuild kBuild{kMaterial, 1, SphereMethod::Auto, false};

// A polynomial in x, y, z as its terms by powers; products of them, and its coefficients in POV-Ray's order.
using Powers = std::tuple<int, int, int>;
using Poly3 = std::map<Powers, double>;

Poly3 times(const Poly3& a, const Poly3& b) {
  Poly3 p;
  for (const auto& [ka, ca] : a) {
    for (const auto& [kb, cb] : b) {
      p[{std::get<0>(ka) + std::get<0>(kb), std::get<1>(ka) + std::get<1>(kb), std::get<2>(ka) + std::get<2>(kb)}] += ca * cb;
    }
  }
  return p;
}

std::vector<double> povOrder(int order, const Poly3& p) {
  std::vector<double> c;
  for (int x = order; x >= 0; --x) {
    for (int y = order - x; y >= 0; --y) {
      for (int z = order - x - y; z >= 0; --z) c.push_back(p.count({x, y, z}) ? p.at({x, y, z}) : 0);
    }
  }
  return c;
}

std::unique_ptr<Object<double>> poly(int order, const Poly3& p, bool sturm = false) {
  return PolyDesc{order, povOrder(order, p), sturm}.make<double>(kBuild);
}

std::optional<Hit<double>> shoot(const Object<double>& o, const glm::dvec3& origin, const glm::dvec3& dir) {
  return o.intersect(Ray<double>{origin, glm::normalize(dir)}, Interval<double>{});
}

// The manual's "torus the hard way" (POV-Ray 3.7 manual §3.4.5.3.5): major radius √40, minor √12.
const std::vector<double> kManualTorus = {1,    0, 0, 0, 2, 0, 0,    2, 0,   //
                                          -104, 0, 0, 0, 0, 0, 0,    0, 0,   //
                                          0,    0, 1, 0, 0, 2, 0,    56, 0,  //
                                          0,    0, 0, 1, 0, -104, 0, 784};

}  // namespace

TEST_CASE("POV-Ray's term order: x's powers from the highest, then y's, then z's", "[poly]") {
  CHECK(povPolyTermCount(2) == 10);
  CHECK(povPolyTermCount(3) == 20);
  CHECK(povPolyTermCount(4) == 35);
  CHECK(povPolyTermCount(7) == 120);
  // Order 2 as the manual's table lists it: x², xy, xz, x, y², yz, y, z², z, 1.
  const std::vector<Monomial> terms = povPolyTerms(2, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const int expected[10][3] = {{2, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 0, 0}, {0, 2, 0},
                               {0, 1, 1}, {0, 1, 0}, {0, 0, 2}, {0, 0, 1}, {0, 0, 0}};
  REQUIRE(terms.size() == 10);
  for (size_t i = 0; i < 10; ++i) {
    CAPTURE(i);
    CHECK(terms[i].c == double(i + 1));
    CHECK(terms[i].x == expected[i][0]);
    CHECK(terms[i].y == expected[i][1]);
    CHECK(terms[i].z == expected[i][2]);
  }
  // Order 3 begins x³, x²y, x²z, x², xy², xyz (the manual's A1–A6).
  const std::vector<Monomial> cubic = povPolyTerms(3, {1, 2, 3, 4, 5, 6, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  REQUIRE(cubic.size() == 6);
  CHECK((cubic[4].x == 1 && cubic[4].y == 2 && cubic[4].z == 0));
  CHECK((cubic[5].x == 1 && cubic[5].y == 1 && cubic[5].z == 1));
  // Entries of the manual's table for orders 5 to 7: A41, A42, A81, A85 and A120.
  const auto powersAt = [](int order, size_t index) {
    std::vector<double> c(povPolyTermCount(order), 0);
    c[index - 1] = 1;
    const Monomial m = povPolyTerms(order, c).at(0);
    return std::tuple{m.x, m.y, m.z};
  };
  CHECK(powersAt(5, 41) == std::tuple{0, 3, 0});
  CHECK(powersAt(6, 41) == std::tuple{1, 3, 0});
  CHECK(powersAt(7, 41) == std::tuple{2, 3, 0});
  CHECK(powersAt(5, 42) == std::tuple{0, 2, 3});
  CHECK(powersAt(7, 42) == std::tuple{2, 2, 3});
  CHECK(powersAt(6, 81) == std::tuple{0, 0, 3});
  CHECK(powersAt(7, 81) == std::tuple{1, 0, 3});
  CHECK(powersAt(7, 85) == std::tuple{0, 7, 0});
  CHECK(powersAt(7, 120) == std::tuple{0, 0, 0});
}

TEST_CASE("the manual's quartic torus is hit where the torus is, by both root finders", "[poly]") {
  const auto torus = TorusDesc{std::sqrt(40.0), std::sqrt(12.0)}.make<double>(kBuild);
  for (const bool sturm : {false, true}) {
    CAPTURE(sturm);
    REQUIRE(kManualTorus.size() == povPolyTermCount(4));
    const auto quartic = PolyDesc{4, kManualTorus, sturm}.make<double>(kBuild);
    CHECK(std::string(quartic->name()) == "Quartic");
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (int i = 0; i < 2000; ++i) {
      const glm::dvec3 origin(30 * unit(rng), 30 * unit(rng), 30 * unit(rng)), target(10 * unit(rng), 4 * unit(rng), 10 * unit(rng));
      const Ray<double> ray{origin, glm::normalize(target - origin)};
      const auto a = torus->intersect(ray, {}), b = quartic->intersect(ray, {});
      CAPTURE(i);
      REQUIRE(bool(a) == bool(b));
      if (!a) continue;
      CHECK(b->t == Approx(a->t).epsilon(1e-9));
      CHECK(glm::length(b->normal - a->normal) < 1e-6);
      CHECK(quartic->inside(ray.at(a->t + 1e-6)) == torus->inside(ray.at(a->t + 1e-6)));
    }
  }
}

TEST_CASE("a cubic x³ + y³ + z³ = 1: hits along the axes with the gradient's normal", "[poly]") {
  const auto c = poly(3, {{{3, 0, 0}, 1}, {{0, 3, 0}, 1}, {{0, 0, 3}, 1}, {{0, 0, 0}, -1}});
  CHECK(std::string(c->name()) == "Cubic");
  CHECK_FALSE(c->bounds());
  const auto hit = shoot(*c, {5, 0, 0}, {-1, 0, 0});
  REQUIRE(hit);
  CHECK(hit->t == Approx(4).epsilon(1e-12));
  CHECK(hit->normal == glm::dvec3(1, 0, 0));
  CHECK(c->inside({0, 0, 0}));
  CHECK_FALSE(c->inside({1, 1, 0}));
  test::paritySweep<double>(*c, glm::dvec3(-2), glm::dvec3(2), 1e-6, 41);
}

TEST_CASE("order 6, x⁶ + y⁶ + z⁶ = 1, a rounded cube: on the axes and the diagonal", "[poly]") {
  for (const bool sturm : {false, true}) {
    const auto cube = poly(6, {{{6, 0, 0}, 1}, {{0, 6, 0}, 1}, {{0, 0, 6}, 1}, {{0, 0, 0}, -1}}, sturm);
    const auto side = shoot(*cube, {0, -4, 0}, {0, 1, 0});
    REQUIRE(side);
    CHECK(side->t == Approx(3).epsilon(1e-12));
    CHECK(side->normal == glm::dvec3(0, -1, 0));
    const auto corner = shoot(*cube, {3, 3, 3}, {-1, -1, -1});
    REQUIRE(corner);
    CHECK(corner->t == Approx(std::sqrt(3.0) * (3 - std::pow(3.0, -1.0 / 6))).epsilon(1e-12));
    CHECK(glm::length(corner->normal - glm::normalize(glm::dvec3(1))) < 1e-12);
    test::paritySweep<double>(*cube, glm::dvec3(-1), glm::dvec3(1), 1e-6, 42);
  }
}

TEST_CASE("order 7: spheres of radius 1, 2 and 3 cut by the plane x = 0, all crossed by one ray", "[poly]") {
  const Poly3 s = {{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 2}, 1}};
  const auto minus = [&](double k) {
    Poly3 p = s;
    p[{0, 0, 0}] = -k;
    return p;
  };
  const Poly3 f = times(times(times(minus(1), minus(4)), minus(9)), {{{1, 0, 0}, 1}});
  const auto shells = poly(7, f);
  // Along x at height y = 0.6: the spheres at x = ±√(r² − 0.36), and the plane.
  std::vector<double> expected;
  for (const double r : {3.0, 2.0, 1.0}) expected.push_back(5 - std::sqrt(r * r - 0.36));
  expected.push_back(5);
  for (const double r : {1.0, 2.0, 3.0}) expected.push_back(5 + std::sqrt(r * r - 0.36));
  const Ray<double> ray{{-5, 0.6, 0}, {1, 0, 0}};
  double from = 0;
  for (const double t : expected) {
    const auto hit = shells->intersect(ray, {from, 100});
    REQUIRE(hit);
    CHECK(hit->t == Approx(t).epsilon(1e-10));
    from = hit->t;
  }
  CHECK_FALSE(shells->intersect(ray, {from, 100}));
  test::paritySweep<double>(*shells, glm::dvec3(-3), glm::dvec3(3), 1e-6, 43);
}

TEST_CASE("a spawned ray does not find the surface it leaves", "[poly]") {
  const auto quartic = PolyDesc{4, kManualTorus, false}.make<double>(kBuild);
  std::mt19937 rng(44);
  std::uniform_real_distribution<double> unit(-1, 1);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 origin(30 * unit(rng), 30 * unit(rng), 30 * unit(rng)), target(10 * unit(rng), 4 * unit(rng), 10 * unit(rng));
    const auto hit = quartic->intersect(Ray<double>{origin, glm::normalize(target - origin)}, {});
    if (!hit) continue;
    ++hits;
    // Leaving to the outside, as a shadow ray toward a light above the surface would.
    glm::dvec3 dir = glm::normalize(glm::dvec3(unit(rng), unit(rng), unit(rng)));
    if (glm::dot(dir, hit->normal) < 0) dir = -dir;
    const glm::dvec3 start = hit->point + 16 * std::numeric_limits<double>::epsilon() * glm::length(hit->point) * hit->normal;
    const auto again = quartic->intersect(Ray<double>{start, dir}, {});
    CAPTURE(i);
    if (again) CHECK(again->t > 1e-6);
  }
  CHECK(hits > 500);
}

TEST_CASE("sceneinfo lists a poly's nonzero terms", "[poly]") {
  std::ostringstream out;
  PolyDesc{4, kManualTorus, true}.describe(out);
  CHECK(out.str() ==
        "- Order: 4\n- Terms: 1.0000 x^4, 2.0000 x^2 y^2, 2.0000 x^2 z^2, -104.0000 x^2, 1.0000 y^4, 2.0000 y^2 z^2, "
        "56.0000 y^2, 1.0000 z^4, -104.0000 z^2, 784.0000\n- Sturm: yes\n");
}

using rt::test::messageOf;

TEST_CASE("impossible polys are refused where the mistake is: the order, the count, all zero", "[poly]") {
  CHECK(messageOf("poly { 8, <1, 2> }") == "s.pov:2:8: error: the poly order must be from 2 to 7, found 8");
  CHECK(messageOf("poly { 1, <1, 2> }") == "s.pov:2:8: error: the poly order must be from 2 to 7, found 1");
  CHECK(messageOf("quartic { <1, 2, 3> }") == "s.pov:2:19: error: the quartic coefficients need 35 numbers, found 3");
  CHECK(messageOf("cubic { <0,0,0,0, 0,0,0, 0,0,0, 0,0,0, 0,0,0, 0,0,0, 5> }") ==
        "s.pov:2:9: error: the cubic coefficients of x, y and z are all zero");
}
