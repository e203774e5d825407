#include <cmath>
#include <memory>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/shapes/superellipsoid.hpp"
#include "shape_oracle.hpp"

using namespace rt;

namespace {

const Material kMaterial{};

std::unique_ptr<Object<double>> superellipsoid(double e, double n) {
  return SuperellipsoidDesc{e, n}.make<double>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
}

std::string povFailure(const std::string& body) {
  try {
    povray::parsePovRay("#version 3.7;\n" + body, "scene.pov", povray::PovRayOptions{{}, 320, 240, false});
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("the superellipsoid <1, 1> is the unit sphere: hits and normals of random rays", "[superellipsoid]") {
  const auto s = superellipsoid(1, 1);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int r = 0; r < 2000; ++r) {
    const glm::dvec3 origin = glm::dvec3(u(rng), u(rng), u(rng)) * 4.0, target(u(rng), u(rng), u(rng));
    if (glm::length(origin) < 1.2) continue;
    const Ray<double> ray{origin, glm::normalize(target - origin)};
    const double b = glm::dot(origin, ray.dir), c = glm::dot(origin, origin) - 1, disc = b * b - c;
    const auto hit = s->intersect(ray, Interval<double>{});
    if (disc < 1e-6) {
      if (disc < -1e-6) CHECK_FALSE(hit);
      continue;
    }
    REQUIRE(hit);
    CHECK(hit->t == Approx(-b - std::sqrt(disc)).epsilon(1e-12));
    CHECK(glm::length(hit->normal - hit->point) < 1e-9);
    ++hits;
  }
  CHECK(hits > 500);
}

TEST_CASE("a small-exponent superellipsoid is a rounded box", "[superellipsoid]") {
  const auto box = superellipsoid(0.1, 0.1);
  const auto hit = box->intersect({{0.5, 0.3, -5}, {0, 0, 1}}, Interval<double>{});
  REQUIRE(hit);
  CHECK(hit->t == Approx(4).epsilon(1e-3));
  CHECK(hit->normal.z == Approx(-1).epsilon(1e-6));
  CHECK(box->inside({0.9, 0.9, 0.9}));
  CHECK_FALSE(box->inside({0.99, 0.99, 0.99}));  // the rounded corner
  const auto b = box->bounds();
  REQUIRE(b);
  CHECK(b->max == glm::dvec3(1));
}

TEST_CASE("superellipsoid sweeps: crossings against inside()", "[superellipsoid]") {
  unsigned seed = 20;
  for (const glm::dvec2 en : {glm::dvec2(1, 1), glm::dvec2(0.3, 0.6), glm::dvec2(0.2, 1), glm::dvec2(2.5, 0.5),
                              glm::dvec2(1.5, 3)}) {
    CAPTURE(en.x, en.y);
    const auto s = superellipsoid(en.x, en.y);
    test::paritySweep<double>(*s, glm::dvec3(-1), glm::dvec3(1), 1e-6, seed++);
  }
}

TEST_CASE("superellipsoid exponents must be two positive numbers", "[superellipsoid]") {
  CHECK(povFailure("superellipsoid { <0, 1> }\n") ==
        "scene.pov:2:18: error: the superellipsoid exponents must be greater than 0, found <0, 1>");
  CHECK(povFailure("superellipsoid { <1, 1, 1> }\n") ==
        "scene.pov:2:18: error: the superellipsoid exponents need 2 numbers, found 3");
  const SceneDesc course =
      parsePov("camera { location <0,0,5> look_at <0,0,0> }\nsuperellipsoid { <0.5, 0.25> }\n", "s.pov");
  CHECK(std::get<SuperellipsoidDesc>(course.objects.at(0).shape).n == 0.25);
}
