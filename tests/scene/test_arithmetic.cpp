// The precision budget R = (largest coordinate or ray length) ÷ smallest feature and the arithmetic chosen
// from it (docs/reference/stability.md §1.1), on small scenes built here.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "raytrace/scene/arithmetic.hpp"

using rt::Arithmetic;
using rt::OffsetPolicy;
using rt::Tier;
using rt::SphereMethod;

namespace {

rt::SceneDesc withCamera(glm::dvec3 location) {
  rt::SceneDesc s;
  s.camera.location = location;
  return s;
}

// The same scene in the .cli language, which never gets the course tier: the budget tiers alone.
rt::SceneDesc asCs3451(rt::SceneDesc s) {
  s.language = rt::SceneLanguage::Cs3451;
  return s;
}

void add(rt::SceneDesc& s, rt::ShapeDesc shape, std::vector<rt::TransformStep> transforms = {}) {
  rt::ObjectDesc o;
  o.shape = shape;
  o.transforms = std::move(transforms);
  s.objects.push_back(o);
}

}  // namespace

// The extent is the larger of the largest coordinate and the diagonal of the box around the camera and the
// objects' bounding balls (a plane contributes its point nearest the origin): it bounds every ray's length.
TEST_CASE("precision: budget of a simple.pov-like scene") {
  rt::SceneDesc s = withCamera({0, 0, 14});
  add(s, rt::SphereDesc{{0, 0, 0}, 2});
  add(s, rt::PlaneDesc{{0, 1, 0}, -4});
  // Box (−2, −4, −2)…(2, 2, 14): diagonal √(4² + 6² + 16²) = √308, over radius 2.
  CHECK(rt::precisionBudget(s) == Approx(std::sqrt(308.0) / 2));
  const Arithmetic a = rt::chooseArithmetic(asCs3451(s));
  CHECK(a.tier == Tier::Float);
  CHECK(a.sphere == SphereMethod::Textbook);
  CHECK(a.offset == OffsetPolicy::Relative);
  // As a POV file it is the course's own kind of scene: the course tier.
  const Arithmetic course = rt::chooseArithmetic(s);
  CHECK(course.tier == Tier::Course);
  CHECK(course.sphere == SphereMethod::Textbook);
  CHECK(course.offset == OffsetPolicy::Course);
}

TEST_CASE("precision: scenes of planes only, or nothing, have no feature to lose") {
  rt::SceneDesc s = withCamera({0, 0, 0.5});
  CHECK(rt::precisionBudget(s) == 1.0);
  add(s, rt::PlaneDesc{{0, 1, 0}, -40});
  CHECK(rt::precisionBudget(s) == Approx(std::sqrt(40.0 * 40.0 + 0.5 * 0.5)));  // camera to (0, −40, 0)
}

// Each shape alone, seen from the origin, which lies inside the box around its bounding ball (centre m,
// radius ρ): the extent is that box's diagonal 2√3·ρ.
TEST_CASE("precision: every shape's extent and smallest feature") {
  const auto budget = [](rt::ShapeDesc shape) {
    rt::SceneDesc s = withCamera({0, 0, 0});
    add(s, shape);
    return rt::precisionBudget(s);
  };
  const double root3 = std::sqrt(3.0);
  // Sides 4, 5, 3; m = (4/3, 1, 0), ρ = |(4, 0, 0) − m| = √73/3.
  CHECK(budget(rt::TriangleDesc{{0, 0, 0}, {4, 0, 0}, {0, 3, 0}}) == Approx(2 * root3 * std::sqrt(73.0) / 3 / 3));
  // Thinnest 2; m = (4, 0, 0), ρ = |(10, 2, 2)|/2 = 3√3.
  CHECK(budget(rt::BoxDesc{{-1, -1, -1}, {9, 1, 1}}) == Approx(2 * root3 * 3 * root3 / 2));
  // Radius 0.5; m = (0, 0, 5), ρ = 5 + 0.5.
  CHECK(budget(rt::CylinderDesc{{0, 0, 0}, {0, 0, 10}, 0.5}) == Approx(2 * root3 * 5.5 / 0.5));
  // Larger radius 0.25; m = (0, 0.5, 0), ρ = 0.5 + 0.25.
  CHECK(budget(rt::ConeDesc{{0, 0, 0}, 0.25, {0, 1, 0}, 0}) == Approx(2 * root3 * 0.75 / 0.25));
}

// A torus's lengths are its tube and its outer radius; the polynomial shapes are computed in double whatever
// their scale (their kinds' float error is not bounded).
TEST_CASE("precision: the polynomial shapes") {
  rt::SceneDesc s = withCamera({0, 0, 0});
  add(s, rt::TorusDesc{2, 0.5});
  CHECK(rt::precisionBudget(s) == Approx(2 * std::sqrt(3.0) * 2.5 / 0.5));
  CHECK(rt::chooseArithmetic(s).tier == Tier::Double);
  rt::SceneDesc q = withCamera({0, 0, 5});
  add(q, rt::QuadricDesc{{1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1});
  CHECK(rt::chooseArithmetic(q).tier == Tier::Double);
  rt::SceneDesc p = withCamera({0, 0, 5});
  add(p, rt::PolyDesc{2, {1, 0, 0, 0, 1, 0, 0, 1, 0, -1}});
  CHECK(rt::chooseArithmetic(p).tier == Tier::Double);
}

TEST_CASE("precision: transforms scale both the extent and the features") {
  rt::SceneDesc s = withCamera({0, 0, 1});
  add(s, rt::SphereDesc{{0, 0, 0}, 1}, {{rt::TransformStep::Kind::Scale, {0.1, 1, 1}}});
  CHECK(rt::precisionBudget(s) == Approx(2 * std::sqrt(3.0) / 0.1));  // box ±1 holds the camera; thinnest 0.1
  rt::SceneDesc t = withCamera({0, 0, 1});
  add(t, rt::SphereDesc{{0, 0, 0}, 1}, {{rt::TransformStep::Kind::Translate, {0, 0, 99}}});
  CHECK(rt::precisionBudget(t) == Approx(100.0));  // the coordinate 100 exceeds the diagonal √(8 + 99²)
}

TEST_CASE("precision: the thresholds R = 50 and R = 10000") {
  // A unit sphere at the origin and the camera at (0, 0, z): box (−1, −1, −1)…(1, 1, z), so R = √(8 + (z+1)²).
  const auto choose = [](double R) {
    rt::SceneDesc s = asCs3451(withCamera({0, 0, std::sqrt(R * R - 8) - 1}));
    add(s, rt::SphereDesc{{0, 0, 0}, 1});
    CHECK(rt::precisionBudget(s) == Approx(R));
    return rt::chooseArithmetic(s);
  };
  CHECK(choose(49.99).tier == Tier::Float);
  CHECK(choose(49.99).sphere == SphereMethod::Textbook);
  CHECK(choose(50.01).tier == Tier::Float);
  CHECK(choose(50.01).sphere == SphereMethod::Robust);
  CHECK(choose(9999.9).tier == Tier::Float);
  CHECK(choose(9999.9).sphere == SphereMethod::Robust);
  CHECK(choose(10000.1).tier == Tier::Double);
  CHECK(choose(10000.1).sphere == SphereMethod::Robust);
}

TEST_CASE("precision: explicit requests win") {
  rt::SceneDesc s = asCs3451(withCamera({0, 0, 1e4}));
  add(s, rt::SphereDesc{{0, 0, 0}, 1});
  const Arithmetic forced = rt::chooseArithmetic(s, {Tier::Float, SphereMethod::Textbook});
  CHECK(forced.tier == Tier::Float);
  CHECK(forced.sphere == SphereMethod::Textbook);
  rt::SceneDesc small = asCs3451(withCamera({0, 0, 5}));
  add(small, rt::SphereDesc{{0, 0, 0}, 1});
  const Arithmetic dbl = rt::chooseArithmetic(small, {Tier::Double, SphereMethod::Auto});
  CHECK(dbl.tier == Tier::Double);
  CHECK(dbl.sphere == SphereMethod::Robust);  // the textbook formula is only ever chosen for float
  CHECK(rt::chooseArithmetic(small, {Tier::Auto, SphereMethod::Robust}).sphere == SphereMethod::Robust);
}

// A POV scene gets the course tier (besides the checks of tier_domain.hpp) while its smallest feature is at
// least 0.002 (twice the course's fixed offset) and its extent at most 1000 (float's ulp there is 6e-5, well
// below the offset).
TEST_CASE("precision: the course tier for course-scale POV scenes only") {
  const auto scene = [](double scale, glm::dvec3 shift) {
    rt::SceneDesc s = withCamera(scale * glm::dvec3(0, 0, 14) + shift);
    add(s, rt::SphereDesc{scale * glm::dvec3(0, 0, 0) + shift, scale * 2});
    add(s, rt::BoxDesc{scale * glm::dvec3(3, 0, 0) + shift, scale * glm::dvec3(3.5, 0.01, 0.5) + shift});
    return s;
  };
  const auto tier = [](const rt::SceneDesc& s) { return rt::chooseArithmetic(s).tier; };
  CHECK(tier(scene(1, glm::dvec3(0))) == Tier::Course);
  // Scaled by 1e-3 the thin box is 1e-5 thick, far below the offset: the budget tiers (the extent counts as
  // at least 1, so R = 1e5 asks for double).
  CHECK(tier(scene(1e-3, glm::dvec3(0))) == Tier::Double);
  // Moved 1e5 away, the coordinates' rounding nears the offset: R ≈ 1e7 asks for double.
  CHECK(tier(scene(1, glm::dvec3(1e5, 0, 0))) == Tier::Double);
  // A .cli scene never gets it, at any scale.
  CHECK(tier(asCs3451(scene(1, glm::dvec3(0)))) == Tier::Float);
  // The thresholds themselves: a feature of exactly 0.002 and an extent of exactly 1000 are inside. (A
  // sphere that small would fail first on the textbook quadratic's error: tests/scene/test_stability_tier_domain.cpp.)
  rt::SceneDesc thin = scene(1, glm::dvec3(0));
  thin.objects[1].shape = rt::BoxDesc{{3, 0, 0}, {3.5, 0.002, 0.5}};
  CHECK(tier(thin) == Tier::Course);
  thin.objects[1].shape = rt::BoxDesc{{3, 0, 0}, {3.5, 0.0019, 0.5}};
  CHECK(tier(thin) == Tier::Float);
  rt::SceneDesc far = withCamera({0, 0, 0});
  add(far, rt::PlaneDesc{{0, 0, 1}, -1000});  // its point nearest the origin, (0, 0, −1000), stands in
  CHECK(rt::sceneScale(far).extent == 1000.0);
  CHECK(tier(far) == Tier::Course);
  far.objects[0].shape = rt::PlaneDesc{{0, 0, 1}, -1000.5};
  CHECK(tier(far) == Tier::Float);
}

// Issue 35: `translate <1e40,0,0> translate <-1e40,0,0>` leaves the sphere where it was, but the course tier
// composes the steps in float, where 1e40 overflows and the sphere vanished. Every partial product counts.
TEST_CASE("precision: the course tier only where float holds every step of every transform") {
  const auto scene = [](double far) {
    rt::SceneDesc s = withCamera({0, 0, 14});
    add(s, rt::SphereDesc{{0, 0, 0}, 2}, {{rt::TransformStep::Kind::Translate, {far, 0, 0}},
                                          {rt::TransformStep::Kind::Translate, {-far, 0, 0}}});
    return s;
  };
  CHECK(rt::sceneScale(scene(1e40)).extent == rt::sceneScale(scene(0)).extent);  // the sphere has not moved
  CHECK(rt::sceneScale(scene(1e40)).largestTransform == 1e40);
  CHECK(rt::chooseArithmetic(scene(1e40)).tier == Tier::Float);
  CHECK(rt::chooseArithmetic(scene(1000)).tier == Tier::Course);
  CHECK(rt::chooseArithmetic(scene(1000.5)).tier == Tier::Float);
}

TEST_CASE("precision: explicit requests win over the course tier, each on its own") {
  rt::SceneDesc s = withCamera({0, 0, 14});
  add(s, rt::SphereDesc{{0, 0, 0}, 2});
  const Arithmetic robust = rt::chooseArithmetic(s, {Tier::Auto, SphereMethod::Robust});
  CHECK(robust.tier == Tier::Course);
  CHECK(robust.sphere == SphereMethod::Robust);
  CHECK(robust.offset == OffsetPolicy::Course);
  const Arithmetic relative = rt::chooseArithmetic(s, {Tier::Auto, SphereMethod::Auto, OffsetPolicy::Relative});
  CHECK(relative.tier == Tier::Course);
  CHECK(relative.sphere == SphereMethod::Textbook);
  CHECK(relative.offset == OffsetPolicy::Relative);
  const Arithmetic dbl = rt::chooseArithmetic(s, {Tier::Double});
  CHECK(dbl.tier == Tier::Double);
  CHECK(dbl.sphere == SphereMethod::Robust);
  CHECK(dbl.offset == OffsetPolicy::Relative);
  // Asked for, the course tier applies outside its domain too (a .cli scene here), with its own offset.
  const Arithmetic course = rt::chooseArithmetic(asCs3451(s), {Tier::Course});
  CHECK(course.tier == Tier::Course);
  CHECK(course.sphere == SphereMethod::Textbook);
  CHECK(course.offset == OffsetPolicy::Course);
}

TEST_CASE("precision: withPrecision calls the lambda with the chosen type") {
  CHECK(rt::withPrecision(Tier::Course, [](auto t) { return sizeof(t); }) == sizeof(float));
  CHECK(rt::withPrecision(Tier::Float, [](auto t) { return sizeof(t); }) == sizeof(float));
  CHECK(rt::withPrecision(Tier::Double, [](auto t) { return sizeof(t); }) == sizeof(double));
}
