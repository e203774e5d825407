// image_map: the pixel a point reads under each mapping, its wrapping and `once`, the two interpolations, the
// colours' decoding as POV-Ray 3.7 decodes them, and the messages of a file that cannot be read.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <stb/stb_image_write.h>

#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/surface/image_map.hpp"
#include "temp_dir.hpp"

using namespace rt;

namespace {

const SourceLoc kAt{std::string("scene.pov"), 1, 1};

// A w×h RGB PNG of the given bytes, row by row from the top.
std::string writePng(const test::TempDir& dir, const std::string& name, int w, int h, const std::vector<unsigned char>& rgb) {
  const std::string path = dir.file(name);
  REQUIRE(stbi_write_png(path.c_str(), w, h, 3, rgb.data(), w * 3) != 0);
  return path;
}

// 4×2 pixels whose red is 10 × the column + 100 × the row (from the top): which pixel a point reads.
std::string writeGrid(const test::TempDir& dir) {
  std::vector<unsigned char> rgb;
  for (int row = 0; row < 2; ++row) {
    for (int column = 0; column < 4; ++column) rgb.insert(rgb.end(), {static_cast<unsigned char>(10 * column + 100 * row), 0, 0});
  }
  return writePng(dir, "grid.png", 4, 2, rgb);
}

// The pixel read at p: its red × 255, rounded, as column + 10 × row; -1 where the map is clear.
int pixelAt(const ImageMap& image, const glm::dvec3& p) {
  const Rgbft c = image.at(p);
  if (c.transmit == 1) return -1;
  return int(std::lround(c.rgb.r * 255)) / 10;
}

SceneDesc povIn(const test::TempDir& dir, const std::string& text) {
  return povray::parsePovRay(text, dir.file("scene.pov"), povray::PovRayOptions{{}, 320, 240, false});
}

}  // namespace

TEST_CASE("image_map: planar lays the image on the unit square of x and y, repeated unless once", "[image_map]") {
  const test::TempDir dir;
  ImageMap image = readImageFile(writeGrid(dir), -1, 1, kAt);
  REQUIRE(image.width == 4);
  REQUIRE(image.height == 2);
  CHECK(pixelAt(image, {0.1, 0.9, 0}) == 0);   // the top row at y near 1
  CHECK(pixelAt(image, {0.9, 0.9, 5}) == 3);   // z does not matter
  CHECK(pixelAt(image, {0.1, 0.1, 0}) == 10);  // the bottom row
  CHECK(pixelAt(image, {0.6, 0.1, 0}) == 12);
  CHECK(pixelAt(image, {0.25, 0.5, 0}) == 1);  // a pixel's lower and left edges belong to it
  CHECK(pixelAt(image, {1.1, -0.1, 0}) == 0);  // repeated
  CHECK(pixelAt(image, {-0.1, 2.1, 0}) == 13);
  image.once = true;
  CHECK(pixelAt(image, {0.6, 0.1, 0}) == 12);
  CHECK(pixelAt(image, {1.1, 0.1, 0}) == -1);
  CHECK(pixelAt(image, {0.5, -0.1, 0}) == -1);
}

TEST_CASE("image_map: spherical and cylindrical go once round the y axis from +x, facing -z at three quarters",
          "[image_map]") {
  const test::TempDir dir;
  ImageMap image = readImageFile(writeGrid(dir), -1, 1, kAt);
  image.mapping = ImageMap::Mapping::Spherical;
  CHECK(pixelAt(image, {1, 0.3, 0.01}) == 0);
  CHECK(pixelAt(image, {0, 0.3, 1}) == 1);
  CHECK(pixelAt(image, {-1, 0.3, 0}) == 2);
  CHECK(pixelAt(image, {0, 0.3, -1}) == 3);
  CHECK(pixelAt(image, {0, -0.3, -1}) == 13);  // below the equator: the bottom row
  CHECK(pixelAt(image, {0, -5, -1}) == 13);
  image.mapping = ImageMap::Mapping::Cylindrical;
  CHECK(pixelAt(image, {0, 0.7, -1}) == 3);
  CHECK(pixelAt(image, {0, 1.3, -2}) == 13);  // v is y, repeated
  image.once = true;
  CHECK(pixelAt(image, {0, 1.3, -2}) == -1);
  CHECK(pixelAt(image, {0, 0.3, 2}) == 11);
}

TEST_CASE("image_map: torus goes round the y axis as the others, and once round the tube of major radius 1",
          "[image_map]") {
  // POV-Ray 3.7 read a 256x256 image of the torus of radius 1 and 0.3 at 8 angles round its tube: row (from the
  // top) 127 on the outer equator, 63 over the top, 255 on the inner rim, 191 under the bottom.
  const test::TempDir dir;
  ImageMap image = readImageFile(writeGrid(dir), -1, 1, kAt);
  image.mapping = ImageMap::Mapping::Torus;
  const auto onTube = [](double round, double tube) {
    const double a = glm::radians(round), b = glm::radians(tube), r = 1 + 0.3 * std::cos(b);
    return glm::dvec3(r * std::cos(a), 0.3 * std::sin(b), r * std::sin(a));
  };
  CHECK(pixelAt(image, onTube(10, 10)) == 0);   // just over the outer equator: the top row
  CHECK(pixelAt(image, onTube(10, -10)) == 10);  // just under it: the bottom row
  CHECK(pixelAt(image, onTube(100, 170)) == 1);  // towards the inner rim from above
  CHECK(pixelAt(image, onTube(190, 190)) == 12);  // past it, from below
  CHECK(pixelAt(image, onTube(280, 90)) == 3);
}

TEST_CASE("image_map: interpolate 2 is bilinear and 4 weights the four nearest pixels by their inverse square distance",
          "[image_map]") {
  const test::TempDir dir;
  // Black over white in the left column, white over white in the right: pixel centres at u 0.25 and 0.75.
  ImageMap image = readImageFile(writePng(dir, "bw.png", 2, 2, {0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255}),
                                 -1, 1, kAt);
  image.interpolation = ImageMap::Interpolation::Bilinear;
  CHECK(image.at({0.25, 0.75, 0}).rgb.r == Approx(0));
  CHECK(image.at({0.375, 0.75, 0}).rgb.r == Approx(0.25));
  CHECK(image.at({0.25, 0.5, 0}).rgb.r == Approx(0.5));
  CHECK(image.at({0, 0.75, 0}).rgb.r == Approx(0.5));  // wrapped round to the right column
  CHECK(image.at({0.375, 0.625, 0}).rgb.r == Approx(1 - 0.75 * 0.75));
  // POV-Ray 3.7's value there on its render of the black and white columns (#version 3.6, so undecoded).
  image.pixels = {{Color(0), 0, 0}, {Color(1), 0, 0}, {Color(0), 0, 0}, {Color(1), 0, 0}};
  CHECK(std::lround(image.at({0.015625, 0.234375, 0}).rgb.r * 255) == 120);
  image.interpolation = ImageMap::Interpolation::NormalizedDistance;
  CHECK(image.at({0.25, 0.75, 0}).rgb.r == Approx(0));
  const double nearBlack = 1 / 0.0625, nearWhite = 1 / 0.5625, farBlack = 1 / 1.0625, farWhite = 1 / 1.5625;
  CHECK(image.at({0.375, 0.75, 0}).rgb.r == Approx((nearWhite + farWhite) / (nearBlack + nearWhite + farBlack + farWhite)));
  // POV-Ray 3.7's values on the same render with interpolate 4.
  CHECK(std::lround(image.at({0.015625, 0.234375, 0}).rgb.r * 255) == 114);
  CHECK(std::lround(image.at({0.140625, 0.234375, 0}).rgb.r * 255) == 24);
  CHECK(std::lround(image.at({0.203125, 0.234375, 0}).rgb.r * 255) == 4);
}

TEST_CASE("image_map: filter I, F and transmit I, F set the pixels of a palette image's index I", "[image_map]") {
  const test::TempDir dir;
  // A 2×1 GIF of indices 1 and 0: (10, 20, 250) and (200, 100, 50).
  const std::string gif = dir.write("pal.gif", std::string("\x47\x49\x46\x38\x37\x61\x02\x00\x01\x00\x81\x00\x00\xc8\x64"
                                                           "\x32\x0a\x14\xfa\x00\x00\x00\x00\x00\x00\x2c\x00\x00\x00"
                                                           "\x00\x02\x00\x01\x00\x00\x08\x05\x00\x03\x00\x08\x08\x00"
                                                           "\x3b",
                                                           44));
  const ImageMap image = readImageFile(gif, -1, 1, kAt, {{1, true, 0.5f}, {0, false, 0.25f}, {1, false, 0.125f}});
  REQUIRE(image.pixels.size() == 2);
  CHECK(image.pixels[0].rgb == Color(10 / 255.0f, 20 / 255.0f, 250 / 255.0f));
  CHECK(image.pixels[0].transmit == 0.5f);
  CHECK(image.pixels[0].filter == 0.125f);
  CHECK(image.pixels[1].transmit == 0);
  CHECK(image.pixels[1].filter == 0.25f);
  // A colour image has no indices: its pixels keep their own.
  const ImageMap rgb = readImageFile(writeGrid(dir), -1, 1, kAt, {{0, true, 1}});
  CHECK(rgb.pixels[0].transmit == 0);
}

TEST_CASE("image_map: a 3.7 scene decodes the file from sRGB into its working gamma; an older one takes it as it is",
          "[image_map]") {
  const test::TempDir dir;
  writePng(dir, "grey.png", 1, 1, {128, 64, 255});
  const auto colour = [&](const std::string& head, const std::string& map) {
    const SceneDesc s = povIn(dir, head + "\nplane { z, 0 pigment { image_map { png \"grey.png\"" + map + " } } }\n");
    REQUIRE(s.objects.size() == 1);
    REQUIRE(s.objects[0].texture);
    return s.objects[0].texture->at(glm::dvec3(0.5, 0.5, 0)).pigment;
  };
  const double srgb128 = std::pow((128 / 255.0 + 0.055) / 1.055, 2.4);
  CHECK(colour("#version 3.7;", "").r == Approx(srgb128));
  CHECK(colour("#version 3.7;", "").b == Approx(1));
  CHECK(colour("#version 3.7; global_settings { assumed_gamma 2.2 }", "").r == Approx(std::pow(srgb128, 1 / 2.2)));
  CHECK(colour("#version 3.7;", " gamma 2").g == Approx(std::pow(64 / 255.0, 2)));
  CHECK(colour("#version 3.6;", "").r == Approx(128 / 255.0));
  CHECK(colour("#version 3.6; global_settings { assumed_gamma 1 }", "").r == Approx(128 / 255.0));
}

TEST_CASE("image_map: a missing or unreadable file is one located error; what is not drawn yet is refused",
          "[image_map]") {
  const test::TempDir dir;
  dir.write("empty.png", "");
  writeGrid(dir);
  dir.write("text.png", "not an image");
  // A PNG's signature and header of a 0×0 image, and one of 60000×60000 pixels (whose rows are missing).
  const std::string header("\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52", 16);
  dir.write("zero.png", header + std::string("\x00\x00\x00\x00\x00\x00\x00\x00\x08\x02\x00\x00\x00\xb4\xe9\xeb\x45", 17));
  dir.write("huge.png", header + std::string("\x00\x00\xea\x60\x00\x00\xea\x60\x08\x02\x00\x00\x00\x00\x00\x00\x00", 17));
  const auto failure = [&](const std::string& map) {
    try {
      povIn(dir, "#version 3.7;\nplane { z, 0 pigment { image_map { " + map + " } } }\n");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(failure("png \"nowhere.png\"") == dir.file("scene.pov") + ":2:40: error: cannot find the image map \"nowhere.png\"");
  CHECK(failure("png \"text.png\"") ==
        dir.file("scene.pov") + ":2:40: error: cannot read the image map \"" + dir.file("text.png") + "\": unknown image type");
  CHECK(failure("png \"zero.png\"") ==
        dir.file("scene.pov") + ":2:40: error: cannot read the image map \"" + dir.file("zero.png") + "\": unknown image type");
  CHECK(failure("png \"huge.png\"") ==
        dir.file("scene.pov") + ":2:40: error: cannot read the image map \"" + dir.file("huge.png") + "\": unknown image type");
  CHECK(failure("png \"empty.png\" map_type 3") ==
        dir.file("scene.pov") + ":2:52: error: 'image_map map_type 3' is not supported yet");
  CHECK(failure("png \"empty.png\" use_index") ==
        dir.file("scene.pov") + ":2:52: error: 'image_map use_index' is not supported yet");
  CHECK(failure("png \"empty.png\" filter 1") == dir.file("scene.pov") + ":2:52: error: 'filter' needs a palette index and an amount");
  const auto after = [&](const std::string& rest) {
    try {
      povIn(dir, "#version 3.7;\nplane { z, 0 pigment { image_map { png \"grid.png\" } " + rest + " } }\n");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(after("transmit 0.5") == dir.file("scene.pov") + ":2:53: error: 'transmit' is not supported yet");
  CHECK(failure("tiff \"empty.png\"") == dir.file("scene.pov") + ":2:36: error: 'image_map tiff' is not supported yet");
}

TEST_CASE("material_map: a palette image's index, or else its red's 8-bit value, picks a texture modulo their count",
          "[image_map]") {
  const test::TempDir dir;
  writeGrid(dir);
  // The 2×1 GIF above: indices 1 and 0, whose reds (10 and 200) would pick otherwise.
  dir.write("pal.gif", std::string("\x47\x49\x46\x38\x37\x61\x02\x00\x01\x00\x81\x00\x00\xc8\x64\x32\x0a\x14\xfa\x00"
                                   "\x00\x00\x00\x00\x00\x2c\x00\x00\x00\x00\x02\x00\x01\x00\x00\x08\x05\x00\x03\x00"
                                   "\x08\x08\x00\x3b",
                                   44));
  const auto picked = [&](const std::string& file, const glm::dvec3& p) {
    const SceneDesc s = povIn(dir, "#version 3.7;\nplane { z, 0 texture { material_map { " + file +
                                       " texture { pigment { rgb <1, 0, 0> } } texture { pigment { rgb <0, 1, 0> } }"
                                       " texture { pigment { rgb <0, 0, 1> } } } } }\n");
    REQUIRE(s.objects.size() == 1);
    const Color c = s.objects[0].texture->at(p).pigment;
    return c == Color(1, 0, 0) ? 0 : c == Color(0, 1, 0) ? 1 : c == Color(0, 0, 1) ? 2 : -1;
  };
  // The grid's reds 0, 10, 20 (top row) and 130 (bottom right) modulo 3.
  CHECK(picked("png \"grid.png\"", {0.1, 0.75, 0}) == 0);
  CHECK(picked("png \"grid.png\"", {0.3, 0.75, 0}) == 1);
  CHECK(picked("png \"grid.png\"", {0.6, 0.75, 0}) == 2);
  CHECK(picked("png \"grid.png\"", {0.9, 0.25, 0}) == 1);
  CHECK(picked("png \"grid.png\"", {1.1, 0.75, 0}) == 0);  // repeated, as an image_map is
  CHECK(picked("gif \"pal.gif\"", {0.25, 0.5, 0}) == 1);
  CHECK(picked("gif \"pal.gif\"", {0.75, 0.5, 0}) == 0);
}

TEST_CASE("material_map: one without a texture is an error; once and interpolate in it are refused", "[image_map]") {
  const test::TempDir dir;
  writeGrid(dir);
  const auto failure = [&](const std::string& map) {
    try {
      povIn(dir, "#version 3.7;\nplane { z, 0 texture { material_map { " + map + " } } }\n");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(failure("png \"grid.png\"") == dir.file("scene.pov") + ":2:24: error: material_map needs a texture");
  CHECK(failure("png \"grid.png\" once texture { pigment { rgb 1 } }") ==
        dir.file("scene.pov") + ":2:54: error: 'material_map once' is not supported yet");
  CHECK(failure("png \"grid.png\" interpolate 2 texture { pigment { rgb 1 } }") ==
        dir.file("scene.pov") + ":2:54: error: 'material_map interpolate' is not supported yet");
  CHECK(failure("png \"grid.png\" texture { pigment { rgb 1 } } scale 2") == "no error");
}
