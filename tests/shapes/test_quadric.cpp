#include <cmath>
#include <memory>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/shapes/quadric.hpp"
#include "parse_message.hpp"
#include "shape_oracle.hpp"

using namespace rt;

namespace {

const Material kMaterial{};

std::unique_ptr<Object<double>> quadric(glm::dvec3 squares, glm::dvec3 products, glm::dvec3 linear, double constant) {
  return QuadricDesc{squares, products, linear, constant}.make<double>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
}

std::optional<Hit<double>> shoot(const Object<double>& o, const glm::dvec3& origin, const glm::dvec3& dir) {
  return o.intersect(Ray<double>{origin, dir}, Interval<double>{});
}

}  // namespace

TEST_CASE("a quadric sphere is hit where the sphere is, and its inside is where the equation is negative",
          "[quadric]") {
  const auto s = quadric({1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1);
  const auto hit = shoot(*s, {0, 0, -5}, {0, 0, 1});
  REQUIRE(hit);
  CHECK(hit->t == Approx(4).epsilon(1e-12));
  CHECK(hit->normal == glm::dvec3(0, 0, -1));
  CHECK(s->inside({0, 0, 0}));
  CHECK_FALSE(s->inside({0, 1.01, 0}));
  CHECK_FALSE(s->bounds());
  CHECK(std::string(s->name()) == "Quadric");
}

TEST_CASE("a paraboloid y = x² + z² from above: the hit and the gradient's normal", "[quadric]") {
  const auto p = quadric({1, 0, 1}, {0, 0, 0}, {0, -1, 0}, 0);
  const auto hit = shoot(*p, {0.5, 5, 0}, {0, -1, 0});
  REQUIRE(hit);
  CHECK(hit->t == Approx(4.75).epsilon(1e-12));
  CHECK(glm::length(hit->normal - glm::normalize(glm::dvec3(1, -1, 0))) < 1e-12);
  CHECK(p->inside({0, 1, 0}));  // above the bowl's floor, where x² + z² − y < 0
  // A mixed term: the saddle z = xy, f = xy − z, its normal along the gradient (y, x, −1).
  const auto saddle = quadric({0, 0, 0}, {1, 0, 0}, {0, 0, -1}, 0);
  const auto down = shoot(*saddle, {1, 2, 5}, {0, 0, -1});
  REQUIRE(down);
  CHECK(down->t == Approx(3).epsilon(1e-12));
  CHECK(glm::length(down->normal - glm::normalize(glm::dvec3(2, 1, -1))) < 1e-12);
}

TEST_CASE("a ray along a quadric cylinder's axis never meets it", "[quadric]") {
  const auto c = quadric({1, 1, 0}, {0, 0, 0}, {0, 0, 0}, -1);
  CHECK_FALSE(shoot(*c, {0.5, 0, -5}, {0, 0, 1}));
  const auto side = shoot(*c, {0, 0, 0}, {1, 0, 0});
  REQUIRE(side);
  CHECK(side->t == Approx(1).epsilon(1e-12));
  CHECK(side->normal == glm::dvec3(1, 0, 0));
}

TEST_CASE("quadric sweeps: crossings against inside() on a hyperboloid and a cone", "[quadric]") {
  const auto hyperboloid = quadric({1, -1, 1}, {0, 0, 0}, {0, 0, 0}, -1);
  test::paritySweep<double>(*hyperboloid, glm::dvec3(-3), glm::dvec3(3), 1e-6, 21);
  const auto cone = quadric({1, 1, -1}, {0, 0, 0}, {0, 0, 0}, 0);
  test::paritySweep<double>(*cone, glm::dvec3(-3), glm::dvec3(3), 1e-6, 22);
  const auto saddle = quadric({0, 0, 0}, {1, 0, 0}, {0, 0, -1}, 0);
  test::paritySweep<double>(*saddle, glm::dvec3(-3), glm::dvec3(3), 1e-6, 23);
}

// A CSG asks for the next hit from the last one; a hit at or before the interval's start would repeat forever.
TEST_CASE("each next hit lies strictly beyond the last, whatever the direction's length", "[quadric]") {
  const auto paraboloid = quadric({1, 0, 1}, {0, 0, 0}, {0, -1, 0}, 0);
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int i = 0; i < 20000; ++i) {
    const glm::dvec3 origin(3 * unit(rng), 3 * unit(rng), 3 * unit(rng));
    const glm::dvec3 dir = glm::dvec3(unit(rng), unit(rng), unit(rng)) * std::pow(10.0, 2 * unit(rng));
    double from = 0;
    for (int k = 0; k < 4; ++k) {
      const auto hit = paraboloid->intersect(Ray<double>{origin, dir}, {from, 1e300});
      if (!hit) break;
      CAPTURE(i, k);
      REQUIRE(hit->t > from);
      from = hit->t;
    }
  }
}

using rt::test::messageOf;

TEST_CASE("a quadric with no x, y or z in it is refused where its coefficients begin", "[quadric]") {
  CHECK(messageOf("quadric { <0,0,0>, <0,0,0>, <0,0,0>, 1 }") ==
        "s.pov:2:11: error: the quadric's coefficients of x, y and z are all zero");
}
