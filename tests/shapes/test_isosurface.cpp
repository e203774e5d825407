#include <cmath>
#include <memory>
#include <random>

#include <catch2/catch.hpp>

#include "raytrace/shapes/isosurface.hpp"

using namespace rt;

namespace {

const Material kMaterial{};
using Op = Function::Op;

// sqrt(x² + y² + z²) − 1: the unit sphere.
std::shared_ptr<const Function> sphereFunction() {
  return std::make_shared<Function>(
      std::vector<Function::Instr>{{Op::Param, 0}, {Op::Param, 0}, {Op::Mul}, {Op::Param, 1}, {Op::Param, 1}, {Op::Mul},
                                   {Op::Add}, {Op::Param, 2}, {Op::Param, 2}, {Op::Mul}, {Op::Add},
                                   {Op::Math1, Function::Sqrt}, {Op::Const, 0, 1}, {Op::Sub}},
      3, 3);
}

// y: solid below the plane y = 0.
std::shared_ptr<const Function> planeFunction() {
  return std::make_shared<Function>(std::vector<Function::Instr>{{Op::Param, 1}}, 3, 1);
}

std::unique_ptr<Object<double>> isosurface(const IsosurfaceParams& p) {
  return IsosurfaceDesc{std::make_shared<const IsosurfaceParams>(p)}.make<double>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
}

}  // namespace

TEST_CASE("an isosurface of the sphere function is the unit sphere: hits and normals of random rays", "[isosurface]") {
  IsosurfaceParams d;
  d.function = sphereFunction();
  d.min = glm::dvec3(-2);
  d.max = glm::dvec3(2);
  const auto s = isosurface(d);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int r = 0; r < 500; ++r) {
    const glm::dvec3 origin = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng))) * 3.0, target(u(rng) * 0.9, u(rng) * 0.9, 0);
    const Ray<double> ray{origin, target - origin};
    // The sphere's nearer root of |o + t·d|² = 1.
    const double a = glm::dot(ray.dir, ray.dir), b = glm::dot(origin, ray.dir), c = glm::dot(origin, origin) - 1;
    const double disc = b * b - a * c;
    const auto hit = s->intersect(ray, {0, 100});
    if (disc < 1e-3) continue;  // grazing rays: either answer is within the accuracy
    REQUIRE(hit);
    ++hits;
    const double t = (-b - std::sqrt(disc)) / a;
    CHECK(hit->t == Approx(t).margin(1e-6));
    CHECK(glm::length(hit->point) == Approx(1).margin(1e-6));
    // The normal is POV-Ray's forward difference one accuracy (0.001) long: within about that of the true one.
    CHECK(glm::length(hit->normal - glm::normalize(hit->point)) < 1e-3);
  }
  CHECK(hits > 100);
  // From inside, the far root.
  const auto out = s->intersect(Ray<double>{{0, 0, 0}, {0, 0, 2}}, {0, 100});
  REQUIRE(out);
  CHECK(out->t == Approx(0.5).margin(1e-7));
  CHECK(out->normal.z == Approx(1).margin(1e-6));  // the z difference straight along the normal
  CHECK(s->inside({0.5, 0, 0}));
  CHECK(!s->inside({1.5, 0, 0}));
  CHECK(!s->inside({3, 0, 0}));  // outside the container
}

TEST_CASE("an isosurface's normal is POV-Ray's: forward differences one accuracy long", "[isosurface]") {
  // y + 1000·x², hit at the origin from above: the true gradient is (0, 1, 0), but the differences over 0.001
  // are (0.001, 0.001, 0), as POV-Ray's trace() shows at the crests of isocacti.pov's ridges.
  IsosurfaceParams d;
  d.function = std::make_shared<Function>(
      std::vector<Function::Instr>{{Op::Param, 1}, {Op::Param, 0}, {Op::Param, 0}, {Op::Mul}, {Op::Const, 0, 1000},
                                   {Op::Mul}, {Op::Add}},
      3, 3);
  d.min = glm::dvec3(-2);
  d.max = glm::dvec3(2);
  const auto hit = isosurface(d)->intersect(Ray<double>{{0, 1, 0}, {0, -1, 0}}, {0, 100});
  REQUIRE(hit);
  CHECK(hit->normal.x == Approx(std::sqrt(0.5)).epsilon(1e-4));
  CHECK(hit->normal.y == Approx(std::sqrt(0.5)).epsilon(1e-4));
  CHECK(hit->normal.z == Approx(0).margin(1e-9));
}

TEST_CASE("an isosurface shows its container where it cuts the solid, unless open", "[isosurface]") {
  IsosurfaceParams d;
  d.function = planeFunction();
  const auto closed = isosurface(d);
  // Below y = 0 the ray enters the box inside the solid: the box's face.
  const Ray<double> low{{0, -0.5, -5}, {0, 0, 1}};
  const auto face = closed->intersect(low, {0, 100});
  REQUIRE(face);
  CHECK(face->t == 4);
  CHECK(face->normal == glm::dvec3(0, 0, -1));
  // From above, the plane itself.
  const auto top = closed->intersect(Ray<double>{{0.25, 5, 0.5}, {0, -1, 0}}, {0, 100});
  REQUIRE(top);
  CHECK(top->t == Approx(5).margin(1e-7));
  CHECK(glm::length(top->normal - glm::dvec3(0, 1, 0)) < 1e-6);
  // Leaving the box inside the solid: its far face.
  const auto far = closed->intersect(Ray<double>{{0, -0.5, 0}, {0, 0, 1}}, {0, 100});
  REQUIRE(far);
  CHECK(far->t == 1);
  CHECK(far->normal == glm::dvec3(0, 0, 1));
  d.open = true;
  const auto open = isosurface(d);
  CHECK(!open->intersect(low, {0, 100}));
  CHECK(open->intersect(Ray<double>{{0.25, 5, 0.5}, {0, -1, 0}}, {0, 100}));
}

TEST_CASE("an isosurface in a sphere container is cut by the sphere", "[isosurface]") {
  IsosurfaceParams d;
  d.function = planeFunction();
  d.sphere = true;
  d.center = {0, 0, 0};
  d.radius = 2;
  const auto s = isosurface(d);
  const auto hit = s->intersect(Ray<double>{{0, -1, -5}, {0, 0, 1}}, {0, 100});
  REQUIRE(hit);
  CHECK(hit->t == Approx(5 - std::sqrt(3.0)).margin(1e-12));
  CHECK(glm::length(hit->normal - glm::dvec3(0, -1, -std::sqrt(3.0)) / 2.0) < 1e-12);
  CHECK(s->bounds()->min == glm::dvec3(-2));
  CHECK(s->bounds()->max == glm::dvec3(2));
}

TEST_CASE("an isosurface whose max_gradient is too low misses the surface, as POV-Ray's does", "[isosurface]") {
  // 100·y² − 1 is negative for |y| < 0.1; along this ray its slope reaches 12, and with the default
  // max_gradient 1.1 the values at the ends of the ray's stretch in the box (5.25 both) rule out a crossing.
  IsosurfaceParams d;
  d.function = std::make_shared<Function>(
      std::vector<Function::Instr>{{Op::Param, 1}, {Op::Param, 1}, {Op::Mul}, {Op::Const, 0, 100}, {Op::Mul},
                                   {Op::Const, 0, 1}, {Op::Sub}},
      3, 2);
  d.open = true;
  d.min = glm::dvec3(-1, -10, -1);
  d.max = glm::dvec3(1, 10, 1);
  const Ray<double> ray{{0.1, 1.25, -5}, {0, -0.25, 1}};
  CHECK(!isosurface(d)->intersect(ray, {0, 100}));
  d.maxGradient = 15;
  const auto hit = isosurface(d)->intersect(ray, {0, 100});
  REQUIRE(hit);
  CHECK(hit->t == Approx(4.6).margin(1e-6));
  CHECK(glm::length(hit->normal - glm::dvec3(0, 1, 0)) < 1e-6);
}
