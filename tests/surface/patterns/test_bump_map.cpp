// bump_map against POV-Ray 3.7's renders: an orthographic view of plane { -z, 0 } through an 8×8 grey PNG, lit
// by parallel lights along ±x, ±y and −z (ambient 0, diffuse 1, assumed_gamma 1, a 16-bit PPM), from whose
// five greys the bent normal at a pixel was solved; the normal was `normal { bump_map { png "b8.png" … }
// scale 2 translate <-0.5, 0, 0> }`.
#include <catch2/catch.hpp>
#include <stb/stb_image_write.h>

#include <string>
#include <vector>

#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/surface/texture.hpp"
#include "temp_dir.hpp"

namespace rt {
namespace {

// The image's greys, row by row from the top.
const unsigned char kGreys[64] = {102, 153, 204, 255, 0,   0,   204, 255, 51,  51,  255, 102, 51,  204, 51,  102,
                                  153, 153, 0,   0,   255, 204, 255, 153, 204, 51,  102, 204, 0,   51,  0,   102,
                                  255, 0,   102, 102, 255, 51,  153, 51,  0,   204, 0,   51,  102, 102, 0,   255,
                                  204, 255, 0,   204, 51,  153, 255, 51,  204, 0,   51,  255, 102, 153, 51,  0};

struct Sample {
  glm::dvec2 point;  // on the plane z = 0
  glm::dvec3 normal;
};

void check(const std::string& modifiers, const std::vector<Sample>& samples) {
  const test::TempDir dir;
  std::vector<unsigned char> rgb;
  for (unsigned char g : kGreys) rgb.insert(rgb.end(), {g, g, g});
  REQUIRE(stbi_write_png(dir.file("b8.png").c_str(), 8, 8, 3, rgb.data(), 8 * 3) != 0);
  const SceneDesc s = povray::parsePovRay("plane { -z, 0 normal { bump_map { png \"b8.png\" " + modifiers +
                                              " } scale 2 translate <-0.5, 0, 0> } }",
                                          dir.file("scene.pov"), povray::PovRayOptions{{}, 320, 240, false});
  REQUIRE(s.objects.size() == 1);
  const Texture& t = *s.objects[0].texture;
  for (const Sample& e : samples) {
    INFO(modifiers << " at " << e.point.x << ", " << e.point.y);
    const glm::dvec3 n = t.bent({e.point, 0}, {0, 0, -1});
    CHECK(n.x == Approx(e.normal.x).margin(1e-4));
    CHECK(n.y == Approx(e.normal.y).margin(1e-4));
    CHECK(n.z == Approx(e.normal.z).margin(1e-4));
  }
}

TEST_CASE("bump_map: the normal through three heights a pixel apart, as POV-Ray bends it", "[patterns][bump_map]") {
  check("bump_size 1", {{{0.21875, 0.71875}, {0.07413, 0.66711, -0.74125}},
                        {{0.65625, 0.53125}, {0.09535, 0.28605, -0.95346}},
                        {{0.78125, 0.21875}, {-0.36514, -0.18258, -0.91287}},
                        {{0.34375, 0.15625}, {0.32445, -0.48666, -0.81111}},
                        {{0.53125, 0.90625}, {-0.08165, -0.57155, -0.81650}},
                        {{0.90625, 0.40625}, {0.09535, -0.28603, -0.95346}}});
  check("bump_size 1 interpolate 2", {{{0.21875, 0.71875}, {0.05493, 0.30728, -0.95003}},
                                      {{0.65625, 0.53125}, {0.08779, 0.33949, -0.93651}},
                                      {{0.78125, 0.21875}, {0.01248, -0.04058, -0.99910}},
                                      {{0.34375, 0.15625}, {0.23621, -0.39180, -0.88920}},
                                      {{0.53125, 0.90625}, {-0.11550, -0.39215, -0.91263}},
                                      {{0.90625, 0.40625}, {0.06610, -0.26736, -0.96132}}});
  check("bump_size 1 interpolate 4", {{{0.21875, 0.71875}, {0.05229, 0.32342, -0.94481}},
                                      {{0.65625, 0.53125}, {0.06840, 0.29548, -0.95290}},
                                      {{0.78125, 0.21875}, {-0.00427, -0.03713, -0.99930}},
                                      {{0.34375, 0.15625}, {0.29003, -0.44971, -0.84477}},
                                      {{0.53125, 0.90625}, {-0.10781, -0.39775, -0.91113}},
                                      {{0.90625, 0.40625}, {0.08716, -0.27162, -0.95845}}});
  check("bump_size 2 once", {{{0.21875, 0.71875}, {0.09666, 0.87005, -0.48338}},
                             {{0.65625, 0.53125}, {0.16904, 0.50709, -0.84515}},
                             {{0.78125, 0.21875}, {-0.59629, -0.29814, -0.74536}},
                             {{0.34375, 0.15625}, {0.45585, -0.68377, -0.56980}},
                             {{0.53125, 0.90625}, {-0.11547, -0.80829, -0.57736}},
                             {{0.90625, 0.40625}, {0.16904, -0.50709, -0.84515}}});
}

TEST_CASE("bump_map: without bump_size the normal's 0.5; map types other than planar are refused", "[patterns][bump_map]") {
  const test::TempDir dir;
  std::vector<unsigned char> rgb;
  for (unsigned char g : kGreys) rgb.insert(rgb.end(), {g, g, g});
  REQUIRE(stbi_write_png(dir.file("b8.png").c_str(), 8, 8, 3, rgb.data(), 8 * 3) != 0);
  const auto read = [&](const std::string& normal) {
    return povray::parsePovRay("plane { -z, 0 normal { " + normal + " } }", dir.file("scene.pov"),
                               povray::PovRayOptions{{}, 320, 240, false});
  };
  const SceneDesc s = read("bump_map { png \"b8.png\" use_color }");
  REQUIRE(s.objects.size() == 1);
  CHECK(s.objects[0].texture->layers[0].normal->amount == 0.5);
  std::string message = "no error";
  try {
    read("bump_map { png \"b8.png\" map_type 1 }");
  } catch (const Error& e) {
    message = e.what();
  }
  CHECK(message == dir.file("scene.pov") + ":1:24: error: 'bump_map map_type 1' is not supported yet");
}

}  // namespace
}  // namespace rt
