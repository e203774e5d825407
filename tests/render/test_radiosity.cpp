// POV-Ray's radiosity drawn with -gi (render/radiosity.hpp, docs/gi.md "POV-Ray's radiosity"): the options a
// block chooses, and closed forms inside a sphere, whose inner points all see every part of it alike.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/render/irradiance_prepass.hpp"
#include "raytrace/render/radiosity.hpp"
#include "raytrace/render/renderer.hpp"
#include "pov_scene.hpp"

using namespace rt;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// A closed sphere of radius 10 seen from its centre, kd = a on a white pigment, no light: only emission lights.
SceneDesc furnace(const std::string& radiosity, double a, const std::string& surface) {
  return test::pov("global_settings { assumed_gamma 1 radiosity { " + radiosity + " } }\n"
                   "camera { location 0 look_at -y }\n"
                   "#default { finish { ambient 0.3 diffuse " + std::to_string(a) + " } }\n" + surface);
}

RenderOptions options(const SceneDesc& scene, int threads = 1) {
  RenderOptions o;
  o.threads = threads;
  useRadiosity(o, scene);
  return o;
}

// The mean of a picture's red channel.
float mean(const Image& image) {
  double sum = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) sum += image.at(x, y).r;
  }
  return float(sum / (image.width() * image.height()));
}

}  // namespace

TEST_CASE("radiosity: a block's settings choose the gathering, its levels and the cache", "[radiosity]") {
  const SceneDesc defaults = test::pov("global_settings { radiosity { } }\n");
  const RenderOptions d = options(defaults);
  CHECK(d.gi.enabled);
  CHECK(d.gi.radiosity);
  CHECK(d.gi.samples == std::vector<int>{64, 1});  // count 35, at least 64
  CHECK(d.gi.bounceCount() == 2);                   // recursion_limit 2
  CHECK(*d.gi.cache == 0.3f);                       // error_bound 1.8 / 2, at most 0.3
  const RenderOptions c = options(test::pov(
      "global_settings { radiosity { count 200 error_bound 0.5 recursion_limit 3 brightness 2 gray_threshold 0.4 } }\n"));
  CHECK(c.gi.samples == std::vector<int>{200, 1});
  CHECK(c.gi.bounceCount() == 3);
  CHECK(*c.gi.cache == 0.25f);
  CHECK(c.gi.brightness == 2);
  CHECK(c.gi.grayThreshold == 0.4f);
  CHECK(options(test::pov("global_settings { radiosity { count 1000 error_bound 0.1 } }\n")).gi.samples[0] == 256);
  CHECK(*options(test::pov("global_settings { radiosity { error_bound 0.1 } }\n")).gi.cache == 0.1f);
  CHECK(options(test::pov("global_settings { radiosity { recursion_limit 1000 } }\n")).gi.bounceCount() == 16);
  // -gi on the command line keeps its own samples, levels and cache; a scene without the block changes nothing.
  RenderOptions own;
  own.gi.enabled = true;
  useRadiosity(own, defaults);
  CHECK(own.gi.radiosity);
  CHECK(own.gi.samples == std::vector<int>{64, 16});
  CHECK(!own.gi.cache);
  RenderOptions none;
  useRadiosity(none, test::pov("sphere { 0, 1 }\n"));
  CHECK(!none.gi.enabled);
  CHECK(!none.gi.radiosity);
}

TEST_CASE("radiosity furnace: a uniformly emitting sphere of albedo a returns E·(1 + a + … + a^L)", "[radiosity]") {
  // Every gather ray meets the same radiance, so there is no variance: level L (the last) returns E, each level
  // above E + a·(the one below). POV-Ray 3.7 measured (E = 0.2, a = 0.5, 40 × 30, its linear mean):
  // recursion_limit 1: 0.3005, 2: 0.3515, 3: 0.3763, brightness 2 at 2: 0.5972; the 3.7 ambient (0.3 here) is
  // not there. As L grows it tends to E/(1 − a).
  const std::string sphere = "sphere { 0, 10 pigment { rgb 1 } finish { emission 0.2 } }\n";
  for (const auto& [limit, expected] : {std::pair{1, 0.3f}, std::pair{2, 0.35f}, std::pair{3, 0.375f}}) {
    CAPTURE(limit);
    const SceneDesc s = furnace("recursion_limit " + std::to_string(limit), 0.5, sphere);
    CHECK_THAT(render(s, 4, 3, options(s)).at(1, 1).r, WithinRel(expected, 1e-5f));
  }
  const SceneDesc bright = furnace("brightness 2", 0.5, sphere);
  CHECK_THAT(render(bright, 4, 3, options(bright)).at(1, 1).r, WithinRel(0.6f, 1e-5f));
  const SceneDesc deep = furnace("count 1 recursion_limit 40", 0.5, sphere);
  CHECK_THAT(render(deep, 2, 2, options(deep)).at(1, 1).r, WithinRel(0.2f / (1 - 0.5f), 1e-5f));
}

TEST_CASE("radiosity: a sphere half of which emits lights its dark half by a·(E/2)·(1 + a), within the noise",
          "[radiosity]") {
  // Inside a sphere every point sees each part of the wall in proportion to its area, so with the upper half
  // emitting E and recursion_limit 2 a level-2 hit returns its own emission (E/2 on average), a level-1 hit
  // that plus a·(one level-2 ray), and a point of the dark half a·(E/2)(1 + a). Each first-level ray returns at
  // most E(1 + a), so the mean of N has a standard error at most E(1 + a)/(2√N); the picture's 12 points are
  // allowed 5 of them.
  const double a = 0.6, e = 1;
  const SceneDesc s = furnace("count 256 recursion_limit 2", a,
                              "sphere { 0, 10 pigment { rgb 1 } finish { emission 1 } clipped_by { plane { -y, 0 } } }\n"
                              "sphere { 0, 10 pigment { rgb 1 } clipped_by { plane { y, 0 } } }\n");
  RenderOptions o = options(s);
  o.gi.cache.reset();  // every pixel gathers on its own
  const float expected = float(a * e / 2 * (1 + a));
  CHECK_THAT(mean(render(s, 4, 3, o)), WithinAbs(expected, 5 * e * (1 + a) / (2 * std::sqrt(256.0))));
  // One level short is far outside it.
  const SceneDesc one = furnace("count 256 recursion_limit 1", a,
                                "sphere { 0, 10 pigment { rgb 1 } finish { emission 1 } clipped_by { plane { -y, 0 } } }\n"
                                "sphere { 0, 10 pigment { rgb 1 } clipped_by { plane { y, 0 } } }\n");
  RenderOptions o1 = options(one);
  o1.gi.cache.reset();
  CHECK(std::abs(mean(render(one, 4, 3, o1)) - expected) > 0.1f);
}

TEST_CASE("radiosity: the cached picture has the same bits for any number of threads", "[radiosity]") {
  const SceneDesc s = test::pov(
      "global_settings { assumed_gamma 1 radiosity { count 64 recursion_limit 2 } }\n"
      "camera { location <0, 1, -4> look_at 0 }\n"
      "light_source { <2, 4, -3>, 1 }\n"
      "plane { y, -1 pigment { rgb <1, 0.5, 0.3> } }\n"
      "sphere { 0, 1 pigment { rgb 1 } finish { diffuse 0.7 } }\n"
      "sphere { <1.5, 0, 1>, 0.5 pigment { rgb 0.2 } finish { emission 2 } }\n");
  const Image one = render(s, 24, 18, options(s, 1));
  const Image three = render(s, 24, 18, options(s, 3));
  for (int y = 0; y < 18; ++y) {
    for (int x = 0; x < 24; ++x) CHECK(one.at(x, y) == three.at(x, y));
  }
}

TEST_CASE("radiosity: where a gathered ray lands an area light lights as a point light at its centre",
          "[radiosity]") {
  // The floor seen lies in the disc's shadow of every grid point, so only gathered light reaches it; the plate
  // under the light's centre hides the centre, not the grid, from the walls the gathered rays meet. POV-Ray 3.7
  // draws the two scenes with the same bits (16 × 12, mean 97.8 of 255 both); sampling the grid where a
  // gathered ray lands would make the area light's picture far brighter.
  const auto scene = [](const std::string& light) {
    return test::pov("global_settings { assumed_gamma 1 radiosity { count 64 recursion_limit 1 } }\n"
                     "camera { location <0, -8, 0> look_at <0, -10, 0> angle 20 }\n"
                     "light_source { <0, 5, 0> rgb 1 " + light + " }\n"
                     "box { <-0.1, 4.9, -0.1>, <0.1, 4.95, 0.1> pigment { rgb 1 } }\n"
                     "disc { 0, y, 3 pigment { rgb 1 } }\n"
                     "sphere { 0, 10 pigment { rgb 1 } }\n");
  };
  const SceneDesc area = scene("area_light <4, 0, 0>, <0, 0, 4>, 4, 4");
  const SceneDesc point = scene("");
  const Image a = render(area, 8, 6, options(area));
  const Image p = render(point, 8, 6, options(point));
  CHECK(mean(p) > 0.05f);
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < 8; ++x) CHECK(a.at(x, y) == p.at(x, y));
  }
}

TEST_CASE("radiosity: the cache's prepass traces no shadow ray where no gathered ray lands", "[radiosity]") {
  // The prepass keeps the records alone; the light of the eye's hits goes into pixels it throws away. Every
  // gathered ray from the floor leaves for the sky, so the area light's 4 shadow rays a hit are never needed.
  const SceneDesc scene = test::pov("global_settings { radiosity { count 64 } }\n"
                                    "camera { location <0, 4, -4> look_at 0 }\n"
                                    "light_source { <0, 5, 0> rgb 1 area_light x, z, 2, 2 }\n"
                                    "plane { y, 0 pigment { rgb 1 } }\n");
  const RenderOptions o = options(scene);
  const Scene<double> built(scene, chooseArithmetic(scene, o.arithmetic));
  RayCounts counts;
  prepareIrradianceCache(built, Camera<double>(scene.camera, 8, 6), o, &counts, nullptr);
  CHECK(counts.eye == 48);
  CHECK(counts.cacheRecords > 0);
  CHECK(counts.gather > 0);
  CHECK(counts.shadow == 0);
}
