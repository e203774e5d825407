// POV-Ray's height_field (shapes/height_field): an image's heights over the unit square, read as POV-Ray reads
// them, split into triangles as POV-Ray splits them (both measured once with trace() in POV-Ray 3.7).
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/shapes/height_field.hpp"
#include "raytrace/shapes/make_object.hpp"
#include "raytrace/shapes/mesh.hpp"
#include "temp_dir.hpp"

using namespace rt;

namespace {

// A 2×2 16-bit grey PNG whose top-left pixel is 65535 and the others 0.
const std::string kPeak16(
    "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x02\x00\x00\x00\x02\x10\x00\x00"
    "\x00\x00\x07\x4d\x8e\xbb\x00\x00\x00\x0d\x49\x44\x41\x54\x78\xda\x63\xf8\xff\x9f\x01\x02\x00\x10\xf9\x01\xff"
    "\x54\x63\xc1\x6f\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82",
    70);
// A 2×2 palette PNG of indices 3, 0 over 1, 2, its palette's colours no grey ramp.
const std::string kPalette(
    "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x02\x00\x00\x00\x02\x08\x03\x00"
    "\x00\x00\x45\x68\xfd\x16\x00\x00\x00\x0c\x50\x4c\x54\x45\xff\x00\x00\xfe\x00\x07\xfd\x01\x0e\xfc\x01\x15\x24"
    "\xc8\x6b\x2f\x00\x00\x00\x0e\x49\x44\x41\x54\x78\xda\x63\x60\x66\x60\x60\x64\x02\x00\x00\x19\x00\x07\x25\x6a"
    "\x63\xbb\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82",
    95);
// A 2×1 8-bit RGB PNG: (153, 0, 0) and (1, 2, 0).
const std::string kRgb(
    "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x02\x00\x00\x00\x01\x08\x02\x00"
    "\x00\x00\x7b\x40\xe8\xdd\x00\x00\x00\x0f\x49\x44\x41\x54\x78\xda\x63\x98\xc9\xc0\xc0\xc8\xc4\x00\x00\x03\xa4"
    "\x00\x9d\x91\x69\xd2\xb8\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82",
    72);

// A 4×3 GIF of palette indices 8 4 5 7 / 1 3 10 9 / 6 0 2 11 (its colours matched to its palette apart).
const std::string kGif(
    "\x47\x49\x46\x38\x39\x61\x04\x00\x03\x00\xf3\x00\x00\x00\x00\x00\x58\x0d\x35\x51\x4a\x00\x4b\x69\x00\x2f\x3e"
    "\x6f\x70\x1c\x68\x39\x69\x42\x8f\x46\x30\x6a\x89\x57\xa4\xb5\x3b\xc1\xb9\x00\xc3\xf5\x33\x00\x00\x00\x00\x00"
    "\x00\x00\x00\x00\x00\x00\x00\x21\xf9\x04\x00\x00\x00\x00\x00\x2c\x00\x00\x00\x00\x04\x00\x03\x00\x00\x04\x09"
    "\x10\x91\x72\xc2\x50\xc9\x00\xb1\x22\x00\x3b",
    92);

SceneDesc povIn(const test::TempDir& dir, const std::string& body) {
  return povray::parsePovRay("#version 3.7;\n" + body, dir.file("scene.pov"),
                             povray::PovRayOptions{{}, 320, 240, false});
}

double heightAt(const Object<double>& o, double x, double z) {
  const auto hit = o.intersect({{x, 5, z}, {0, -1, 0}}, Interval<double>{});
  return hit ? hit->point.y : -1;
}

}  // namespace

TEST_CASE("a height field's pixels: a palette's index over 256, a grey over its largest, red and green as 16 bits",
          "[height_field]") {
  const test::TempDir dir;
  const SourceLoc at{std::string("scene.pov"), 1, 1};
  const HeightImage palette = readHeightImage(dir.write("p.png", kPalette), at);
  REQUIRE(palette.width == 2);
  CHECK(palette.heights == std::vector<double>{3 / 256.0, 0, 1 / 256.0, 2 / 256.0});
  CHECK(readHeightImage(dir.write("g.png", kPeak16), at).heights == std::vector<double>{1, 0, 0, 0});
  std::vector<double> gif;
  for (int index : {8, 4, 5, 7, 1, 3, 10, 9, 6, 0, 2, 11}) gif.push_back(index / 256.0);
  CHECK(readHeightImage(dir.write("s.gif", kGif), at).heights == gif);
  CHECK(readHeightImage(dir.write("c.png", kRgb), at).heights ==
        std::vector<double>{153 * 256 / 65536.0, (1 * 256 + 2) / 65536.0});
}

TEST_CASE("a pot height field: a GIF twice as wide, high bytes on the left and low bytes on the right",
          "[height_field]") {
  // As POV-Ray reads mtmand.pot: its trace() gives (high·256 + low)/65536 at each point of the half-width grid.
  const test::TempDir dir;
  const SourceLoc at{std::string("scene.pov"), 1, 1};
  const HeightImage pot = readHeightImage(dir.write("s.pot", kGif), at, true);
  CHECK(pot.width == 2);
  CHECK(pot.height == 3);
  CHECK(pot.heights == std::vector<double>{(8 * 256 + 5) / 65536.0, (4 * 256 + 7) / 65536.0, (1 * 256 + 10) / 65536.0,
                                           (3 * 256 + 9) / 65536.0, (6 * 256 + 2) / 65536.0, (0 * 256 + 11) / 65536.0});
  const SceneDesc s = povIn(dir, "height_field { pot \"s.pot\" }\n");
  const auto hf = makeObject<double>(s.objects[0], SphereMethod::Auto, 1, false);
  CHECK(heightAt(*hf, 1, 1) == Approx((4 * 256 + 7) / 65536.0));
}

TEST_CASE("a height field lies over the unit square, the image's top row at z = 1, each square split from "
          "(x + 1, z) to (x, z + 1)", "[height_field]") {
  const test::TempDir dir;
  dir.write("peak.png", kPeak16);
  const SceneDesc s = povIn(dir, "height_field { png \"peak.png\" }\n");
  CHECK(std::string(std::get<MeshDesc>(s.objects[0].shape).name()) == "HeightField");
  const auto hf = makeObject<double>(s.objects[0], SphereMethod::Auto, 1, false);
  // POV-Ray's trace() at these points: 0.25, 0.75, 0.25, 0.25.
  CHECK(heightAt(*hf, 0.25, 0.25) == Approx(0.25));
  CHECK(heightAt(*hf, 0.25, 0.75) == Approx(0.75));
  CHECK(heightAt(*hf, 0.75, 0.75) == Approx(0.25));
  CHECK(heightAt(*hf, 0.75, 0.25) == Approx(0.25));
  CHECK(heightAt(*hf, 1.25, 0.25) == -1);
  // Below the surface is inside.
  CHECK(hf->inside({0.1, 0.5, 0.8}));
  CHECK_FALSE(hf->inside({0.1, 0.95, 0.8}));
}

TEST_CASE("a height field's water level removes what lies under it, and smooth blends its normals",
          "[height_field]") {
  const test::TempDir dir;
  dir.write("peak.png", kPeak16);
  const auto cut = makeObject<double>(povIn(dir, "height_field { png \"peak.png\" water_level 0.3 }\n").objects[0],
                                      SphereMethod::Auto, 1, false);
  // POV-Ray's trace(): 0.8 at (0.1, 0.8), nothing at (0.1, 0.25) where the surface is at 0.25.
  CHECK(heightAt(*cut, 0.1, 0.8) == Approx(0.8));
  CHECK(heightAt(*cut, 0.1, 0.25) == -1);
  const auto smooth = makeObject<double>(povIn(dir, "height_field { png \"peak.png\" smooth }\n").objects[0],
                                         SphereMethod::Auto, 1, false);
  const auto hit = smooth->intersect({{0, 5, 0}, {0, -1, 0}}, Interval<double>{});
  REQUIRE(hit);
  // At the corner (0, 0): slopes +1 along z and 0 along x, one-sided.
  CHECK(hit->normal.x == Approx(0).margin(1e-12));
  CHECK(hit->normal.y == Approx(std::sqrt(0.5)));
  CHECK(hit->normal.z == Approx(-std::sqrt(0.5)));
}

TEST_CASE("a height field's missing image, a pot file not a GIF, or a function's size below 2 by 2, is an error "
          "where it is named",
          "[height_field]") {
  const test::TempDir dir;
  const auto failure = [&](const std::string& body) {
    try {
      povIn(dir, body);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(failure("height_field { png \"nowhere.png\" }\n") ==
        dir.file("scene.pov") + ":2:20: error: cannot find the height field image \"nowhere.png\"");
  dir.write("c.pot", kRgb);
  CHECK(failure("height_field { pot \"c.pot\" }\n") ==
        dir.file("scene.pov") + ":2:20: error: the pot file \"" + dir.file("c.pot") +
            "\" is not a GIF of an even width");
  CHECK(failure("height_field { function 1, 10 { x } }\n") ==
        dir.file("scene.pov") +
            ":2:16: error: a height field function's size must be at least 2 by 2, as in `function 100, 100 { … }`");
}

TEST_CASE("a height field of a function: f(x, y, 0) over the grid, y from the top row, in 16 bits, a pigment's grey",
          "[height_field]") {
  const test::TempDir dir;
  const auto field = [&](const std::string& f) {
    return makeObject<double>(povIn(dir, "height_field { function 3, 3 { " + f + " } }\n").objects[0],
                              SphereMethod::Auto, 1, false);
  };
  // POV-Ray's trace() straight down at these points, to its 6 decimals.
  CHECK(heightAt(*field("x"), 0.5, 0.5) == Approx(0.499985).margin(1e-6));
  CHECK(heightAt(*field("y"), 0.5, 0) == Approx(0.999985).margin(1e-6));
  CHECK(heightAt(*field("y"), 0.5, 0.5) == Approx(0.499985).margin(1e-6));
  CHECK(heightAt(*field("pigment { rgb <0.2, 0.5, 0.8> }"), 0.5, 0.5) == Approx(0.445084).margin(1e-6));
  // Values past [0, 1] wrap around, as 16-bit numbers do.
  const auto wrapped = field("2 * x - 0.5");
  CHECK(heightAt(*wrapped, 0.01, 0.5) == Approx(0.500015).margin(1e-6));
  CHECK(heightAt(*wrapped, 0.99, 0.5) == Approx(0.499970).margin(1e-6));
}
