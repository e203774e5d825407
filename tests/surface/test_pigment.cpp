// Patterns, maps and waves at sample points, against the values the POV-Ray 3.7 manual defines.
#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "raytrace/surface/pattern.hpp"
#include "raytrace/surface/pigment.hpp"

namespace rt {
namespace {

std::shared_ptr<const Pattern> pattern(const char* name, glm::dvec3 v = glm::dvec3(0)) {
  const PatternKind* kind = patternKind(name);
  REQUIRE(kind != nullptr);
  return kind->make(PatternArgs{v, kind->needsVector});
}

std::shared_ptr<const Pigment> solid(Color c) {
  auto p = std::make_shared<Pigment>();
  p->solid.rgb = c;
  return p;
}

TEST_CASE("pigment: checker alternates unit cubes along every axis; a face belongs to the cube above it", "[pigment]") {
  const auto checker = pattern("checker");
  CHECK(checker->blocks() == 2);
  CHECK(checker->value({0.5, 0.5, 0.5}) == 0);
  CHECK(checker->value({1.5, 0.5, 0.5}) == 1);
  CHECK(checker->value({1.5, 1.5, 0.5}) == 0);
  CHECK(checker->value({-0.5, 0.5, 0.5}) == 1);
  CHECK(checker->value({-0.5, -0.5, -0.5}) == 1);
  // On the plane y = 0, whatever the rounding of the hit point.
  CHECK(checker->value({0.5, -1e-12, 0.5}) == 0);
  CHECK(checker->value({0.5, 1e-12, 0.5}) == 0);
}

TEST_CASE("pigment: the continuous patterns' values", "[pigment]") {
  CHECK(pattern("gradient", {0, 1, 0})->value({3, 0.25, 7}) == 0.25);
  CHECK(pattern("gradient", {2, 0, 0})->value({0.25, 0, 0}) == 0.5);
  const auto radial = pattern("radial");
  CHECK(radial->value({1, 0, 0}) == Approx(0).margin(1e-12));
  CHECK(radial->value({0, 0, -1}) == Approx(0.25));
  CHECK(radial->value({-1, 0, 0}) == Approx(0.5));
  CHECK(radial->value({0, 0, 1}) == Approx(0.75));
  CHECK(pattern("onion")->value({0, 2.25, 0}) == Approx(0.25));
  CHECK(pattern("spherical")->value({0, 0.25, 0}) == Approx(0.75));
  CHECK(pattern("spherical")->value({3, 0, 0}) == 0);
  CHECK(pattern("cylindrical")->value({0.6, 5, 0.8}) == Approx(0));
  CHECK(pattern("boxed")->value({0.5, -0.75, 0.25}) == Approx(0.25));
  CHECK(pattern("planar")->value({9, -0.25, 9}) == Approx(0.75));
  CHECK(patternKind("square") == nullptr);
}

TEST_CASE("pigment: a colour map interpolates between its entries and holds its ends", "[pigment]") {
  Pigment p;
  p.pattern = pattern("gradient", {1, 0, 0});
  p.map = {{0.25, solid(Color(1, 0, 0))}, {0.75, solid(Color(0, 0, 1))}};
  CHECK(p.at({0.1, 0, 0}).rgb == Color(1, 0, 0));
  CHECK(p.at({0.9, 0, 0}).rgb == Color(0, 0, 1));
  const Color mid = p.at({0.5, 0, 0}).rgb;
  CHECK(mid.r == Approx(0.5f));
  CHECK(mid.b == Approx(0.5f));
  // The pattern repeats every unit, below 0 too.
  CHECK(p.at({-0.9, 0, 0}).rgb == Color(1, 0, 0));
  // frequency 2 and phase 0.5: x = 0.1 reads 0.7.
  p.frequency = 2;
  p.phase = 0.5;
  CHECK(p.at({0.1, 0, 0}).rgb.b == Approx(0.9f));
  // A triangle wave reads 2v below a half and 2 − 2v above.
  p.frequency = 1;
  p.phase = 0;
  p.wave = Wave::Triangle;
  CHECK(p.at({0.75, 0, 0}).rgb.r == Approx(0.5f));
}

TEST_CASE("pigment: a block pattern picks its list's pigments, which its transforms move too", "[pigment]") {
  Pigment p;
  p.pattern = pattern("checker");
  p.list = {solid(Color(1)), solid(Color(0))};
  p.fromTexture = glm::inverse(glm::scale(glm::dmat4(1), glm::dvec3(2)));
  CHECK(p.at({1.5, 0.5, 0.5}).rgb == Color(1));
  CHECK(p.at({2.5, 0.5, 0.5}).rgb == Color(0));
  CHECK(anyColour(p, [](const Rgbft& c) { return c.rgb == Color(0); }));
  CHECK_FALSE(anyColour(p, [](const Rgbft& c) { return c.transmit > 0; }));
}

TEST_CASE("pigment: average mixes its map's pigments, each weighted by its entry's value", "[pigment]") {
  Pigment p;
  p.average = true;
  p.map = {{1, solid(Color(1, 0, 0))}, {3, solid(Color(0, 0, 1))}};
  const Rgbft c = p.at(glm::dvec3(0.3, 7, -2));
  CHECK(c.rgb.r == Approx(0.25f));
  CHECK(c.rgb.g == 0);
  CHECK(c.rgb.b == Approx(0.75f));
}

}  // namespace

// POV-Ray's values of `function { pattern { pigment_pattern { gradient x color_map { [0 rgb <1,0,0>] [0.5 rgb
// <0,1,0>] [1 rgb <0,0,1>] } } } }` at x = 0, 0.25, 0.5 and 0.9999, and of `pigment_pattern { rgbft <0.2, 0.5,
// 0.9, 0.3, 0.4> }`: the colour's grey, filter and transmit left out.
TEST_CASE("pigment: pigment_pattern is its pigment's grey, as POV-Ray prints it", "[pigment]") {
  auto ramp = std::make_shared<Pigment>();
  ramp->pattern = pattern("gradient", glm::dvec3(1, 0, 0));
  ramp->map = {{0, solid({1, 0, 0})}, {0.5, solid({0, 1, 0})}, {1, solid({0, 0, 1})}};
  PatternArgs args;
  args.pigment = ramp;
  const auto grey = patternKind("pigment_pattern")->make(args);
  CHECK(grey->value({0, 0, 0}) == Approx(0.297).epsilon(1e-6));
  CHECK(grey->value({0.25, 0, 0}) == Approx(0.443).epsilon(1e-6));
  CHECK(grey->value({0.5, 0, 0}) == Approx(0.589).epsilon(1e-6));
  CHECK(grey->value({0.9999, 0, 0}) == Approx(0.114095).epsilon(1e-5));
  auto filtered = std::make_shared<Pigment>();
  filtered->solid = {Color(0.2f, 0.5f, 0.9f), 0.3f, 0.4f};
  args.pigment = filtered;
  CHECK(patternKind("pigment_pattern")->make(args)->value({1, 2, 3}) == Approx(0.4565).epsilon(1e-6));
}

}  // namespace rt
