// Fog and sky: fog against the colours real POV-Ray 3.7 gave (linear, read back from its sRGB pictures), ground
// fog's density integral against a numerical one, and the sky's layers.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "raytrace/surface/environment.hpp"

namespace rt {
namespace {

TEST_CASE("environment: constant fog mixes as POV-Ray's does, with filter and transmit", "[environment]") {
  // POV-Ray: a red sphere (ambient 1) 4 units away, fog rgbft <0.3, 0.5, 0.2, f, t> distance 4.5.
  struct Case {
    float filter, transmit;
    Color expected;
  } cases[] = {{0, 0, {0.584f, 0.296f, 0.120f}}, {1, 0, {0.301f, 0.296f, 0.120f}}, {0.5f, 0, {0.445f, 0.296f, 0.120f}},
               {0, 1, {1, 0, 0}}};
  for (const Case& k : cases) {
    Fog fog;
    fog.colour = {Color(0.3f, 0.5f, 0.2f), k.filter, k.transmit};
    fog.distance = 4.5;
    const Color c = fog.over(Color(1, 0, 0), glm::dvec3(0, 0, -5), glm::dvec3(0, 0, 1), 4);
    CHECK(c.r == Approx(k.expected.r).margin(0.004));
    CHECK(c.g == Approx(k.expected.g).margin(0.004));
    CHECK(c.b == Approx(k.expected.b).margin(0.004));
  }
  // A ray that leaves the scene sees the fog's colour, less what it transmits.
  Fog fog;
  fog.colour = {Color(0.3f, 0.5f, 0.2f), 0, 0};
  fog.distance = 4.5;
  CHECK(fog.over(Color(1), glm::dvec3(0), glm::dvec3(0, 0, 1), std::numeric_limits<double>::infinity()) ==
        Color(0.3f, 0.5f, 0.2f));
  fog.distance = 0;  // POV-Ray: no fog
  CHECK(fog.over(Color(1), glm::dvec3(0), glm::dvec3(0, 0, 1), 10) == Color(1));
}

TEST_CASE("environment: ground fog thins above its offset as POV-Ray's density integrates", "[environment]") {
  Fog fog;
  fog.type = Fog::Type::Ground;
  fog.colour = {Color(1), 0, 0};
  fog.distance = 3;
  fog.offset = 1;
  fog.alt = 2;
  const glm::dvec3 origin(0, -2, 0), dir = glm::normalize(glm::dvec3(1, 1, 0));
  const double depth = 9;
  // The midpoint rule on the density 1 below the offset, 1/(1 + ((h − offset)/alt)²) above.
  double thickness = 0;
  const int steps = 200000;
  for (int i = 0; i < steps; ++i) {
    const double h = (origin + dir * ((i + 0.5) * depth / steps)).y;
    thickness += (h <= fog.offset ? 1 : 1 / (1 + std::pow((h - fog.offset) / fog.alt, 2))) * depth / steps;
  }
  const float kept = float(std::exp(-thickness / fog.distance));
  CHECK(fog.over(Color(0), origin, dir, depth).r == Approx(1 - kept).epsilon(1e-5));
  // Upward to infinity the integral is finite: alt·π/2.
  const float up = fog.over(Color(0), glm::dvec3(0, 1, 0), glm::dvec3(0, 1, 0), std::numeric_limits<double>::infinity()).r;
  CHECK(up == Approx(1 - std::exp(-M_PI / 3)).epsilon(1e-6));
}

TEST_CASE("environment: ground fog has half its density at offset + alt, as POV-Ray draws it", "[environment]") {
  // POV-Ray 3.7, 16-bit linear output: horizontal rays 11 units long through fog_type 2, distance 10,
  // fog_offset 0, fog_alt 1, white over black. At height 1.125 the fog is 0.44138 as thick as below 0.
  Fog fog;
  fog.type = Fog::Type::Ground;
  fog.colour = {Color(1), 0, 0};
  fog.distance = 10;
  fog.alt = 1;
  const double heights[] = {1.375, 1.125, 0.625, 0.125, -0.875};
  const float povray[] = {0.31650f, 0.38462f, 0.54661f, 0.66145f, 0.66712f};
  for (size_t i = 0; i < 5; ++i) {
    CHECK(fog.over(Color(0), glm::dvec3(0, heights[i], -1), glm::dvec3(0, 0, 1), 11).r == Approx(povray[i]).margin(3e-5));
  }
}

// Values POV-Ray 3.7 wrote in 16-bit linear light: an orthographic camera at z = −1 looking along +z at a
// black plane z = 10 through white fog, so that each pixel is the fog over a depth of 11 from (x, y, −1).
struct FogPixel {
  double x, y;
  float povray;
};

void checkFog(const Fog& fog, const FogPixel (&pixels)[4]) {
  for (const FogPixel& p : pixels) {
    CHECK(fog.over(Color(0), glm::dvec3(p.x, p.y, -1), glm::dvec3(0, 0, 1), 11).r == Approx(p.povray).margin(3e-5));
  }
}

TEST_CASE("environment: turbulence thins a constant fog as in POV-Ray's pictures", "[environment]") {
  // fog { distance 20 rgb 1 turbulence <0.3, 1, 2> turb_depth 0.8 octaves 4 omega 0.6 lambda 2.5 }
  Fog fog;
  fog.colour = {Color(1), 0, 0};
  fog.distance = 20;
  fog.turbulence.amount = {0.3, 1, 2};
  fog.turbulence.octaves = 4;
  fog.turbulence.omega = 0.6f;
  fog.turbulence.lambda = 2.5f;
  fog.turbDepth = 0.8;
  checkFog(fog, {{-1.875, 1.375, 0.22705f}, {-0.625, 0.625, 0.23900f}, {0.625, -0.375, 0.34069f}, {1.875, -1.375, 0.20758f}});
  // Without turbulence, 1 − e^(−11/20); a ray that leaves the scene keeps the fog's whole colour.
  fog.turbulence.amount = glm::dvec3(0);
  CHECK(fog.over(Color(0), glm::dvec3(0), glm::dvec3(0, 0, 1), 11).r == Approx(1 - std::exp(-0.55)).epsilon(1e-6));
  fog.turbulence.amount = glm::dvec3(1);
  CHECK(fog.over(Color(0), glm::dvec3(0), glm::dvec3(0, 0, 1), std::numeric_limits<double>::infinity()) == Color(1));
}

TEST_CASE("environment: turbulence thins a ground fog as in POV-Ray's pictures", "[environment]") {
  // fog { fog_type 2 distance 15 rgb 1 fog_offset 0.5 fog_alt 2 turbulence 1 turb_depth 0.7 }
  Fog fog;
  fog.type = Fog::Type::Ground;
  fog.colour = {Color(1), 0, 0};
  fog.distance = 15;
  fog.offset = 0.5;
  fog.alt = 2;
  fog.turbulence.amount = glm::dvec3(1);
  fog.turbDepth = 0.7;
  checkFog(fog, {{-1.875, 1.375, 0.33880f}, {-0.625, 0.625, 0.38650f}, {0.625, -0.375, 0.36072f}, {1.875, -1.375, 0.37990f}});
}

TEST_CASE("environment: the sky's layers cover the ones below where they are opaque", "[environment]") {
  auto bottom = std::make_shared<Pigment>();
  bottom->solid = {Color(0, 0, 1), 0, 0};
  auto top = std::make_shared<Pigment>();
  top->solid = {Color(1, 1, 1), 0, 0.75f};
  SkySphere sky;
  sky.layers = {bottom, top};
  const Color c = sky.at(glm::dvec3(0, 1, 0), Color(0));
  CHECK(c.r == Approx(0.25f));
  CHECK(c.b == Approx(1.0f));
  CHECK(sky.bound() == Color(1));
}

TEST_CASE("sky_sphere: before POV-Ray 3.7 a layer's filter passes the layers below untinted", "[environment]") {
  // Values POV-Ray 3.7 wrote (in linear light) for rgbf <1, 0, 0, 0.5> over rgb <0.2, 0.4, 1>.
  auto bottom = std::make_shared<Pigment>();
  bottom->solid = {Color(0.2f, 0.4f, 1), 0, 0};
  auto top = std::make_shared<Pigment>();
  top->solid = {Color(1, 0, 0), 0.5f, 0};
  SkySphere sky;
  sky.layers = {bottom, top};
  sky.filterTints = false;  // #version 3.6
  const Color old = sky.at(glm::dvec3(0, 0, 1), Color(0));
  CHECK(old.r == Approx(0.6f));
  CHECK(old.g == Approx(0.2f));
  CHECK(old.b == Approx(0.5f));
  sky.filterTints = true;  // #version 3.7: the filtered share takes the layer's red
  const Color now = sky.at(glm::dvec3(0, 0, 1), Color(0));
  CHECK(now.r == Approx(0.6f));
  CHECK(now.g == Approx(0.0f));
  CHECK(now.b == Approx(0.0f));
}

}  // namespace
}  // namespace rt
