#include <cmath>
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "pov_scene.hpp"
#include "raytrace/shapes/julia_fractal.hpp"

using namespace rt;

namespace {

const Material kMaterial{};

std::unique_ptr<Object<double>> julia(const JuliaFractalParams& p) {
  return JuliaFractalDesc{std::make_shared<const JuliaFractalParams>(p)}.make<double>(
      ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
}

JuliaFractalParams params(glm::dvec4 constant, bool hypercomplex, JuliaFunction f, int maxIteration, double precision) {
  JuliaFractalParams p;
  p.constant = constant;
  p.hypercomplex = hypercomplex;
  p.function = f;
  p.maxIteration = maxIteration;
  p.precision = precision;
  return p;
}

const JuliaFractalParams& parsed(const SceneDesc& s) { return *std::get<JuliaFractalDesc>(s.objects.at(0).shape).params; }

}  // namespace

TEST_CASE("julia_fractal: quaternion sqr with p = 0 is the unit ball at any iteration count", "[julia_fractal]") {
  // h ← h² keeps |h| ≤ 1 for ever and the bailout radius is 1 + |p| = 1.
  for (int n : {2, 3, 8, 20}) {
    const auto j = julia(params(glm::dvec4(0), false, JuliaFunction::Sqr, n, 20));
    for (const glm::dvec3 dir : {glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::normalize(glm::dvec3(1, 2, -3))}) {
      CHECK(j->inside(0.999 * dir));
      CHECK_FALSE(j->inside(1.001 * dir));
    }
  }
}

TEST_CASE("julia_fractal: the bailout radius is 1 + |p| for quaternions and 4 for hypercomplex numbers",
          "[julia_fractal]") {
  // Quaternion p = −0.5, two terms checked: x² − 0.5 ≤ 1.5 up to x = √2 (POV-Ray's silhouette: 1.416).
  const auto q = julia(params({-0.5, 0, 0, 0}, false, JuliaFunction::Sqr, 2, 20));
  CHECK(q->inside({1.414, 0, 0}));
  CHECK_FALSE(q->inside({1.415, 0, 0}));
  // Quaternion cube, p = −0.5: x³ − 0.5 ≤ 1.5 up to x = ∛2 (POV-Ray's silhouette: 1.260).
  const auto c = julia(params({-0.5, 0, 0, 0}, false, JuliaFunction::Cube, 2, 20));
  CHECK(c->inside({1.2599, 0, 0}));
  CHECK_FALSE(c->inside({1.2600, 0, 0}));
  // Hypercomplex sqr, p = 0: x^(2^(n−1)) ≤ 4, so x ≤ 2 for n = 2 and x ≤ √2 for n = 3 (POV-Ray: 1.998, 1.416).
  const auto h2 = julia(params(glm::dvec4(0), true, JuliaFunction::Sqr, 2, 20));
  CHECK(h2->inside({1.999, 0, 0}));
  CHECK_FALSE(h2->inside({2.001, 0, 0}));
  const auto h3 = julia(params(glm::dvec4(0), true, JuliaFunction::Sqr, 3, 20));
  CHECK(h3->inside({0, 1.414, 0}));
  CHECK_FALSE(h3->inside({0, 1.415, 0}));
  // The bounding box is the bounding sphere's, of the bailout radius.
  const glm::dvec4 p(-0.083, 0, -0.83, -0.025);
  const double r = 1 + glm::length(p);
  const auto b = julia(params(p, false, JuliaFunction::Sqr, 8, 15))->bounds();
  REQUIRE(b);
  CHECK(b->max.x == Approx(r));
  CHECK(b->min.z == Approx(-r));
  CHECK(julia(params(p, true, JuliaFunction::Sqr, 8, 15))->bounds()->max.y == 4);
}

TEST_CASE("julia_fractal: a slice maps a point to the 4-D point on its hyperplane", "[julia_fractal]") {
  // slice <1, 0, 0, 1>, 0.5 over the unit ball (p = 0): w = 0.5·√2 − x, so x² + w² ≤ 1 for x in
  // [(√2 − √6)/4, (√2 + √6)/4] (POV-Ray's inside(): −0.2580 to 0.9660).
  JuliaFractalParams p = params(glm::dvec4(0), false, JuliaFunction::Sqr, 3, 20);
  p.slice = glm::normalize(glm::dvec4(1, 0, 0, 1));
  p.sliceDistance = 0.5;
  const auto j = julia(p);
  const double lo = (std::sqrt(2.0) - std::sqrt(6.0)) / 4, hi = (std::sqrt(2.0) + std::sqrt(6.0)) / 4;
  CHECK(j->inside({lo + 1e-6, 0, 0}));
  CHECK_FALSE(j->inside({lo - 1e-6, 0, 0}));
  CHECK(j->inside({hi - 1e-6, 0, 0}));
  CHECK_FALSE(j->inside({hi + 1e-6, 0, 0}));
}

TEST_CASE("julia_fractal: rays hit where POV-Ray's trace() finds them, with its normal", "[julia_fractal]") {
  struct Case {
    JuliaFractalParams params;
    glm::dvec3 origin, dir, point, normal;
  };
  const glm::dvec4 p1(-0.083, 0, -0.83, -0.025), p2(0.2, 0.1, 0.59, -0.2);
  // POV-Ray 3.7's trace(object, origin, dir, normal), printed to 9 decimals (the normals' last digits cut).
  const Case cases[] = {
      {params(p1, false, JuliaFunction::Sqr, 8, 15), {0, 0, -5}, {0, 0, 1}, {0, 0, -0.975451050}, {0.354414567, 0, -0.93508}},
      {params(p1, false, JuliaFunction::Sqr, 8, 15), {0.3, 0.2, -5}, {0, 0, 1}, {0.3, 0.2, -0.329408274},
       {-0.261167648, 0.380770120, -0.8870}},
      {params(p1, false, JuliaFunction::Sqr, 8, 15), {0.1, -0.2, 5}, {0.1, 0.05, -1}, {0.525730301, 0.012865150, 0.742696991},
       {-0.302942290, -0.006957765, 0.95298}},
      {params(p2, true, JuliaFunction::Sqr, 7, 20), {0.1, 0.1, -5}, {0, 0, 1}, {0.1, 0.1, -0.923848922},
       {0.554636555, 0.587742099, -0.58901}},
      {params(p2, true, JuliaFunction::Sqr, 7, 20), {-0.4, 0.3, -5}, {0.05, 0, 1}, {-0.160097538, 0.3, -0.201950755},
       {-0.732154591, -0.481629005, -0.48}},
      {params(p1, false, JuliaFunction::Cube, 8, 15), {0, 0.1, -5}, {0, 0, 1}, {0, 0.1, -1.146412266},
       {0.778936618, 0.070794574, -0.62309}},
      {params(p1, false, JuliaFunction::Cube, 8, 15), {0.2, -0.3, -5}, {0, 0, 1}, {0.2, -0.3, -1.100918207},
       {-0.195125939, -0.455817604, -0.86}},
  };
  for (const Case& c : cases) {
    const auto hit = julia(c.params)->intersect(Ray<double>{c.origin, c.dir}, {0, 100});
    REQUIRE(hit);
    CHECK(glm::length(hit->point - c.point) < 1e-6);
    CHECK(glm::length(hit->point - (c.origin + hit->t * c.dir)) < 1e-12);
    // The printed normals keep 2 to 5 decimals.
    CHECK(std::abs(hit->normal.x - c.normal.x) < 0.01);
    CHECK(std::abs(hit->normal.y - c.normal.y) < 0.01);
    CHECK(std::abs(hit->normal.z - c.normal.z) < 0.01);
  }
}

TEST_CASE("julia_fractal: a ray leaving a hit does not find it again; one missing the bounding sphere finds nothing",
          "[julia_fractal]") {
  const auto j = julia(params({-0.083, 0, -0.83, -0.025}, false, JuliaFunction::Sqr, 8, 15));
  const auto hit = j->intersect(Ray<double>{{0, 0, -5}, {0, 0, 1}}, {0, 100});
  REQUIRE(hit);
  const auto back = j->intersect(Ray<double>{hit->point, {0, 0, -1}}, {0, 100});
  CHECK_FALSE(back);
  CHECK_FALSE(j->intersect(Ray<double>{{0, 3, -5}, {0, 0, 1}}, {0, 100}));
}

TEST_CASE("julia_fractal: read from a scene, with its defaults and its errors", "[julia_fractal]") {
  const JuliaFractalParams d = parsed(test::pov("julia_fractal { <1, 2, 3, 4> }\n"));
  CHECK(d.constant == glm::dvec4(1, 2, 3, 4));
  CHECK_FALSE(d.hypercomplex);
  CHECK(d.function == JuliaFunction::Sqr);
  CHECK(d.maxIteration == 20);
  CHECK(d.precision == 20);
  CHECK(d.slice == glm::dvec4(0, 0, 0, 1));
  const JuliaFractalParams e =
      parsed(test::pov("julia_fractal { <1, 2, 3, 4> max_iteration 7 hypercomplex precision 0.5 slice <0, 0, 3, 4>, 2 }\n"));
  CHECK(e.hypercomplex);
  CHECK(e.maxIteration == 7);
  CHECK(e.step() == 1);  // precision below 1 counts as 1
  CHECK(glm::length(e.slice - glm::dvec4(0, 0, 0.6, 0.8)) < 1e-15);
  CHECK(e.sliceDistance == 2);
  CHECK(test::povFailure("julia_fractal { <1, 2, 3> }\n") == "scene.pov:2:17: error: the julia_fractal parameter's components need 4 numbers, found 3");
  CHECK(test::povFailure("julia_fractal { <1, 2, 3, 4> slice <1, 0, 0, 0>, 1 }\n") ==
        "scene.pov:2:36: error: the julia_fractal slice normal needs a non-zero fourth component");
  CHECK(test::povFailure("julia_fractal { <1, 2, 3, 4> hypercomplex cube }\n") ==
        "scene.pov:2:43: error: 'cube' with 'hypercomplex' is not supported yet");
  // The hypercomplex functions are keywords there, not the built-in functions: refused, pwr with its numbers.
  CHECK(test::povFailure("julia_fractal { <1, 2, 3, 4> hypercomplex pwr(1, 2) max_iteration 5 }\n") ==
        "scene.pov:2:43: error: 'pwr' is not supported yet");
  CHECK(test::povFailure("julia_fractal { <1, 2, 3, 4> hypercomplex sin max_iteration 5 }\n") ==
        "scene.pov:2:43: error: 'sin' is not supported yet");
}
