#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "raytrace/app/arguments.hpp"
#include "raytrace/render/antialias.hpp"
#include "raytrace/render/renderer.hpp"
#include "command_error.hpp"
#include "pov_scene.hpp"

using namespace rt;
using rt::test::pov;

namespace {

// A white slab to the left of x = 0.3 on black, seen square on: in a 10 × 10 picture its edge crosses the
// sixth column of pixels, a quarter of the way from its right side.
const char* const kEdge =
    "global_settings { assumed_gamma 1 }\n"
    "camera { orthographic location <0,0,-5> look_at 0 right x*4 up y*4 }\n"
    "background { rgb 0 }\n"
    "box { <-5,-5,0>, <0.3,5,1> pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n";

// Spheres of several colours with light, for edges everywhere.
const char* const kSpheres =
    "global_settings { assumed_gamma 1 }\n"
    "camera { location <0,0,-6> look_at 0 }\n"
    "light_source { <5,5,-5> rgb 1 }\n"
    "sphere { <-1,0,0>, 1 pigment { rgb <1,0.2,0.1> } }\n"
    "sphere { <1.2,0.3,1>, 1.3 pigment { checker rgb 1 rgb <0,0,1> scale 0.3 } }\n"
    "plane { y, -1 pigment { rgb 0.6 } }\n";

RenderOptions adaptive(int method, int depth = 3, float jitter = 0) {
  RenderOptions o;
  o.aa.method = method;
  o.aa.depth = depth;
  o.aa.jitter = jitter;
  o.threads = 2;
  return o;
}

uint64_t eyeRays(const SceneDesc& scene, int width, int height, const RenderOptions& options) {
  RayCounts counts;
  RenderMonitor monitor;
  monitor.rays = &counts;
  render(scene, width, height, options, monitor);
  return counts.eye;
}

// refinedPixel() of every pixel of a w × h grid, row by row.
std::vector<char> refinedPixels(const std::vector<Color>& compared, int w, int h, float threshold) {
  std::vector<char> refined;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) refined.push_back(refinedPixel(compared.data(), w, h, x, y, threshold));
  }
  return refined;
}

bool same(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      if (a.at(x, y) != b.at(x, y)) return false;
    }
  }
  return true;
}

}  // namespace

TEST_CASE("anti-aliasing compares colours clipped and raised to 1/2.5, by the sum of the channels' differences",
          "[antialias]") {
  CHECK(aaCompared({2, -1, 1}) == Color(1, 0, 1));
  CHECK(aaCompared({0.03125f, 0, 0}).r == Approx(0.25));  // 2^-5 to the 0.4 is 2^-2
  CHECK(aaDifference({1, 0.5f, 0}, {0, 0.75f, 0.5f}) == 1.75f);
}

TEST_CASE("+AM1 refines a pixel that differs from a neighbour to either side, above or below", "[antialias]") {
  // A 5 × 3 picture: one bright pixel, and a pair whose difference is the threshold exactly (not above it).
  const Color o(0), b(1, 0, 0), t(0.25f, 0, 0);
  const std::vector<Color> picture{o, o, o, o, o,   //
                                   o, b, o, o, t,   //
                                   o, o, o, o, o};
  const std::vector<char> refined = refinedPixels(picture, 5, 3, 0.25f);
  CHECK(refined == std::vector<char>{0, 1, 0, 0, 0,  //
                                     1, 1, 1, 0, 0,  //
                                     0, 1, 0, 0, 0});
  CHECK(refinedPixels(picture, 5, 3, 0.2f) == std::vector<char>{0, 1, 0, 0, 1,  //
                                                                      1, 1, 1, 1, 1,  //
                                                                      0, 1, 0, 0, 1});
  CHECK(refinedPixels(picture, 5, 3, 3.0f) == std::vector<char>(15, 0));
}

TEST_CASE("a flat picture traces each pixel's ray (+AM1) or each corner (+AM2) and nothing more", "[antialias]") {
  const SceneDesc flat = pov("camera { location <0,0,-5> look_at 0 }\nbackground { rgb <0.2,0.4,0.6> }\n");
  CHECK(eyeRays(flat, 40, 30, adaptive(1)) == 40 * 30);
  CHECK(eyeRays(flat, 40, 30, adaptive(2)) == 41 * 31);
  CHECK(eyeRays(flat, 40, 30, adaptive(2, 9, 1)) == 41 * 31);
}

TEST_CASE("anti-aliasing traces as many rays as POV-Ray and gives its colours across an edge", "[antialias]") {
  const SceneDesc edge = pov(kEdge);
  // POV-Ray 3.7's "Pixels" and "Samples" (+V) on this scene at 10 × 10 with -J: 100 + 180 with +A0.3 (two
  // columns of 9 more), 100 + 80 with +R2, 121 + 50, 140 and 310 with +AM2 +R2, +R3, +R4, 121 + 0 with +AM2 +R1.
  // Jittered, +AM1 traces as many; unjittered, the middle of the 3 × 3 grid is each pixel's own ray, not
  // traced again: 20 fewer.
  CHECK(eyeRays(edge, 10, 10, adaptive(1, 3, 1)) == 280);
  CHECK(eyeRays(edge, 10, 10, adaptive(1)) == 260);
  CHECK(eyeRays(edge, 10, 10, adaptive(1, 2)) == 180);
  // +AM2 traces a point on the side of two pixels of the column once, where POV-Ray traces it for each: of each
  // level's points on the pixels' lower and upper sides (one a side, the edge crossing only one square of a
  // level), the 9 between two pixels are traced once.
  CHECK(eyeRays(edge, 10, 10, adaptive(2, 1)) == 121);
  CHECK(eyeRays(edge, 10, 10, adaptive(2, 2)) == 171 - 9);
  CHECK(eyeRays(edge, 10, 10, adaptive(2, 3)) == 261 - 2 * 9);
  CHECK(eyeRays(edge, 10, 10, adaptive(2, 4)) == 431 - 3 * 9);
  // POV-Ray's bytes in the column the edge crosses: (1 + 6 white of 9) / 10 → 0.7 (+AM1); the mean of its
  // subdivided squares (+AM2), 240; the columns on either side stay white and black.
  for (const auto& [method, byte] : {std::pair{1, 218}, std::pair{2, 240}}) {
    Rgb8Image image = renderRgb8(edge, 10, 10, adaptive(method));
    for (int y = 0; y < 10; ++y) {
      CAPTURE(method, y);
      CHECK(int(image.at(4, y)[0]) == 255);
      CHECK(int(image.at(5, y)[0]) == byte);
      CHECK(int(image.at(6, y)[0]) == 0);
    }
  }
}

TEST_CASE("anti-aliased pictures are the same for any threads, tiles and regions, jittered or not", "[antialias]") {
  const SceneDesc scene = pov(kSpheres);
  for (const int method : {1, 2}) {
    for (const float jitter : {0.0f, 1.0f}) {
      CAPTURE(method, jitter);
      RenderOptions one = adaptive(method, 3, jitter);
      one.threads = 1;
      const Image whole = render(scene, 80, 60, one);
      CHECK(same(whole, render(scene, 80, 60, adaptive(method, 3, jitter))));
      // A region that starts and ends inside the renderer's 32-pixel tiles.
      const Region region{13, 7, 71, 45};
      const Image part = render(scene, 80, 60, region, adaptive(method, 3, jitter));
      bool matches = true;
      for (int y = 0; y < part.height(); ++y) {
        for (int x = 0; x < part.width(); ++x) {
          matches = matches && part.at(x, y) == whole.at(x + region.x0, y + (60 - region.y1));
        }
      }
      CHECK(matches);
    }
  }
  // Jitter moves the supersamples, so it changes the picture.
  CHECK_FALSE(same(render(scene, 80, 60, adaptive(1, 3, 0)), render(scene, 80, 60, adaptive(1, 3, 1))));
}

TEST_CASE("anti-aliasing's options are checked before anything is read", "[antialias]") {
  using test::errorOf;
  CHECK(errorOf({"render", "scene.pov", "4", "4", "--aa=3"}) == "--aa must be between 1 and 2, found 3");
  CHECK(errorOf({"render", "scene.pov", "4", "4", "--aa-threshold=3.5"}) ==
        "--aa-threshold must be a number from 0 to 3, found '3.5'");
  CHECK(errorOf({"render", "scene.pov", "4", "4", "--aa-depth=10"}) == "--aa-depth must be between 1 and 9, found 10");
  CHECK(errorOf({"render", "scene.pov", "4", "4", "--jitter=x"}) == "--jitter must be a number from 0 to 1, found 'x'");
  CHECK(errorOf({"render", "scene.pov", "4", "4", "--aa=1", "-ss=3"}) ==
        "--aa and -ss both choose the rays per pixel: give one");
  CHECK(errorOf({"pixelcolor", "scene.pov", "4", "4", "0", "0", "--aa=1"}) == "--aa is for the render command only");
}

TEST_CASE("a tile records anti-aliasing's settings among the options that change pixels", "[antialias]") {
  CHECK(pixelFlags(adaptive(2, 4, 0.5f)) == "--aa=2 --aa-threshold=0.300000012 --aa-depth=4 --jitter=0.5");
  CHECK(pixelFlags(adaptive(1)) == "--aa=1 --aa-threshold=0.300000012 --aa-depth=3");
  CHECK(pixelFlags(RenderOptions{}).empty());
}

TEST_CASE("anti-aliasing's compared colour is within 1e-6 of the power 0.4", "[antialias]") {
  for (float x = 1e-12f; x < 1; x *= 1.0137f) {
    CAPTURE(x);
    REQUIRE(std::abs(aaCompared({x, 0, 0}).r - std::pow(x, 0.4f)) < 1e-6f);
  }
  CHECK(aaCompared({0.03125f, 0.5f, 1}) == Color(0.25f, std::pow(0.5f, 0.4f), 1));
}
