// The sphere sweep: a linear one is spheres joined by the cones tangent to both, against their analytic hits; the
// spline kinds' spheres are the B-spline's and Catmull-Rom's; random rays' crossings keep inside() in step.
#include <cmath>
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/shapes/sphere_sweep.hpp"
#include "pov_scene.hpp"
#include "shape_oracle.hpp"

using namespace rt;

namespace {

const Material kMaterial{};

std::unique_ptr<Object<double>> sweep(SphereSweepDesc::Spline spline, std::vector<SweepSphere> spheres) {
  SphereSweepDesc d;
  d.spline = spline;
  d.spheres = std::move(spheres);
  return d.make<double>(ObjectBuild{kMaterial, 1, SphereMethod::Auto, false});
}

}  // namespace

TEST_CASE("a linear sweep of two equal spheres is a capsule", "[sphere_sweep]") {
  const auto s = sweep(SphereSweepDesc::Spline::Linear, {{{0, 0, 0}, 0.5}, {{2, 0, 0}, 0.5}});
  const auto side = s->intersect({{1, 5, 0}, {0, -1, 0}}, Interval<double>{});
  REQUIRE(side);
  CHECK(side->t == Approx(4.5).epsilon(1e-12));
  CHECK(glm::length(side->normal - glm::dvec3(0, 1, 0)) < 1e-12);
  CHECK(glm::length(side->point - glm::dvec3(1, 0.5, 0)) < 1e-12);
  const auto end = s->intersect({{-5, 0, 0}, {1, 0, 0}}, Interval<double>{});
  REQUIRE(end);
  CHECK(end->t == Approx(4.5).epsilon(1e-12));
  CHECK(glm::length(end->normal - glm::dvec3(-1, 0, 0)) < 1e-12);
  // From inside, the way out.
  const auto out = s->intersect({{1, 0, 0}, {1, 0, 0}}, Interval<double>{});
  REQUIRE(out);
  CHECK(out->t == Approx(1.5).epsilon(1e-12));
  CHECK_FALSE(s->intersect({{1, 0.6, -5}, {0, 0, 1}}, Interval<double>{}));
  CHECK(s->inside({1, 0.4, 0}));
  CHECK_FALSE(s->inside({1, 0.6, 0}));
  CHECK(s->inside({2.4, 0, 0}));
  CHECK_FALSE(s->inside({2.6, 0, 0}));
  const auto box = s->bounds();
  REQUIRE(box);
  CHECK(box->min == glm::dvec3(-0.5, -0.5, -0.5));
  CHECK(box->max == glm::dvec3(2.5, 0.5, 0.5));
}

// Radii 1 and 2 four apart: sin α = 1/4, and the cone ρ·cos α = 1 + x·sin α touches the balls between x = −1/4 and
// x = 4 − 1/2 (the envelope of the spheres, manual §3.4.5.1.13).
TEST_CASE("a linear sweep of two unequal spheres is joined by the cone tangent to both", "[sphere_sweep]") {
  const auto s = sweep(SphereSweepDesc::Spline::Linear, {{{0, 0, 0}, 1}, {{4, 0, 0}, 2}});
  const double cosA = std::sqrt(15.0) / 4;
  for (const double x : {-0.2, 0.0, 2.0, 3.4}) {
    CAPTURE(x);
    const auto hit = s->intersect({{x, 10, 0}, {0, -1, 0}}, Interval<double>{});
    REQUIRE(hit);
    CHECK(hit->t == Approx(10 - (1 + x / 4) / cosA).epsilon(1e-12));
    CHECK(glm::length(hit->normal - glm::dvec3(-0.25, cosA, 0)) < 1e-12);
  }
  // Past the tangent circles, the balls.
  const auto small = s->intersect({{-0.5, 10, 0}, {0, -1, 0}}, Interval<double>{});
  REQUIRE(small);
  CHECK(small->t == Approx(10 - std::sqrt(0.75)).epsilon(1e-12));
  const auto big = s->intersect({{4, 0, 10}, {0, 0, -1}}, Interval<double>{});
  REQUIRE(big);
  CHECK(big->t == Approx(8).epsilon(1e-12));
  CHECK(s->inside({2, (1 + 0.5) / cosA - 1e-9, 0}));
  CHECK_FALSE(s->inside({2, (1 + 0.5) / cosA + 1e-9, 0}));
}

TEST_CASE("a sweep whose sphere holds the next is that sphere", "[sphere_sweep]") {
  const auto s = sweep(SphereSweepDesc::Spline::Linear, {{{0, 0, 0}, 2}, {{0.5, 0, 0}, 0.5}});
  const auto hit = s->intersect({{0, 5, 0}, {0, -1, 0}}, Interval<double>{});
  REQUIRE(hit);
  CHECK(hit->t == Approx(3).epsilon(1e-12));
  CHECK(s->inside({1.9, 0, 0}));
  CHECK_FALSE(s->inside({2.1, 0, 0}));
}

// For control points P0..P3 a segment runs from (P0 + 4·P1 + P2)/6 to (P1 + 4·P2 + P3)/6, through
// (P0 + 23·P1 + 23·P2 + P3)/48 halfway (the uniform cubic B-spline); Catmull-Rom runs from P1 to P2 through
// (−P0 + 9·P1 + 9·P2 − P3)/16.
TEST_CASE("the spline sweeps' spheres are the B-spline's and Catmull-Rom's", "[sphere_sweep]") {
  SphereSweepDesc d;
  d.spheres = {{{0, 0, 0}, 0.5}, {{1, 2, 0}, 1}, {{3, 2, 1}, 2}, {{4, 0, 4}, 0.5}};
  const auto near = [](const SweepSphere& a, glm::dvec4 b) {
    return glm::length(glm::dvec4(a.center, a.radius) - b) < 1e-12;
  };
  const glm::dvec4 p0(0, 0, 0, 0.5), p1(1, 2, 0, 1), p2(3, 2, 1, 2), p3(4, 0, 4, 0.5);
  d.spline = SphereSweepDesc::Spline::BSpline;
  auto spheres = d.linearSpheres();
  REQUIRE(spheres.size() == SphereSweepDesc::kSplineSteps + 1);
  CHECK(near(spheres.front(), (p0 + 4.0 * p1 + p2) / 6.0));
  CHECK(near(spheres[SphereSweepDesc::kSplineSteps / 2], (p0 + 23.0 * p1 + 23.0 * p2 + p3) / 48.0));
  CHECK(near(spheres.back(), (p1 + 4.0 * p2 + p3) / 6.0));
  d.spline = SphereSweepDesc::Spline::Cubic;
  spheres = d.linearSpheres();
  CHECK(near(spheres.front(), p1));
  CHECK(near(spheres[SphereSweepDesc::kSplineSteps / 2], (-p0 + 9.0 * p1 + 9.0 * p2 - p3) / 16.0));
  CHECK(near(spheres.back(), p2));
  // Five points, two segments, sharing the sphere between them.
  d.spheres.push_back({{6, 1, 4}, 1});
  CHECK(d.linearSpheres().size() == 2 * SphereSweepDesc::kSplineSteps + 1);
}

TEST_CASE("a b_spline sweep of evenly spaced collinear spheres is the capsule between the middle two", "[sphere_sweep]") {
  for (const auto spline : {SphereSweepDesc::Spline::BSpline, SphereSweepDesc::Spline::Cubic}) {
    const auto s = sweep(spline, {{{0, 0, 0}, 0.5}, {{1, 0, 0}, 0.5}, {{2, 0, 0}, 0.5}, {{3, 0, 0}, 0.5}});
    const auto end = s->intersect({{-5, 0, 0}, {1, 0, 0}}, Interval<double>{});
    REQUIRE(end);
    CHECK(end->t == Approx(5.5).epsilon(1e-12));
    const auto side = s->intersect({{1.3, 5, 0}, {0, -1, 0}}, Interval<double>{});
    REQUIRE(side);
    CHECK(side->t == Approx(4.5).epsilon(1e-12));
  }
}

TEST_CASE("sphere sweep sweeps: crossings against inside()", "[sphere_sweep]") {
  const std::vector<SweepSphere> spheres = {
      {{-2, 0, 0}, 0.3}, {{-0.5, 1, 0}, 0.6}, {{0.5, -0.5, 0.5}, 0.2}, {{0.6, -0.4, 0.4}, 0.7}, {{2, 0.5, 0}, 0.5}};
  unsigned seed = 40;
  for (const auto spline :
       {SphereSweepDesc::Spline::Linear, SphereSweepDesc::Spline::BSpline, SphereSweepDesc::Spline::Cubic}) {
    const auto s = sweep(spline, spheres);
    test::paritySweep<double>(*s, glm::dvec3(-2.5, -1.5, -1), glm::dvec3(2.5, 1.7, 1.5), 1e-6, seed++);
  }
}

TEST_CASE("a sphere sweep is read with its spline, spheres and tolerance", "[sphere_sweep]") {
  const SceneDesc pov = test::pov(
      "sphere_sweep { linear_spline 2, <0, 0, 0>, 0.5, <1, 1, 0>, 0.25 }\n"
      "sphere_sweep { b_spline 4, 0, 1, x, 1, y, 1, z, 1 tolerance 1e-4 }\n"
      "sphere_sweep { cubic_spline 4, 0, 1, x, 1, y, 1, z, 1 }\n");
  REQUIRE(pov.objects.size() == 3);
  const auto& linear = std::get<SphereSweepDesc>(pov.objects[0].shape);
  CHECK(linear.spline == SphereSweepDesc::Spline::Linear);
  REQUIRE(linear.spheres.size() == 2);
  CHECK(linear.spheres[1].center == glm::dvec3(1, 1, 0));
  CHECK(linear.spheres[1].radius == 0.25);
  CHECK(std::get<SphereSweepDesc>(pov.objects[1].shape).spline == SphereSweepDesc::Spline::BSpline);
  CHECK(std::get<SphereSweepDesc>(pov.objects[1].shape).tolerance == 1e-4);
  CHECK(std::get<SphereSweepDesc>(pov.objects[2].shape).spline == SphereSweepDesc::Spline::Cubic);
}

TEST_CASE("a sphere sweep without its spline, with too few or too many spheres, is refused there", "[sphere_sweep]") {
  CHECK(test::povFailure("sphere_sweep { 2, 0, 1, x, 1 }\n") ==
        "scene.pov:2:16: error: expected linear_spline, b_spline or cubic_spline inside 'sphere_sweep'");
  CHECK(test::povFailure("sphere_sweep { linear_spline 1, 0, 1 }\n") ==
        "scene.pov:2:30: error: a linear_spline sphere_sweep needs a whole number of at least 2 spheres, found 1");
  CHECK(test::povFailure("sphere_sweep { b_spline 3, 0, 1, x, 1, y, 1 }\n") ==
        "scene.pov:2:25: error: a b_spline sphere_sweep needs a whole number of at least 4 spheres, found 3");
  CHECK(test::povFailure("sphere_sweep { linear_spline 2, 0, 1, x, 1, y, 1 }\n") ==
        "scene.pov:2:45: error: more sphere_sweep spheres than the 2 its count gives");
  CHECK(test::povFailure("sphere_sweep { linear_spline 2, 0, -1, x, 1 }\n") ==
        "scene.pov:2:36: error: a sphere_sweep radius must not be negative, found -1");
}
