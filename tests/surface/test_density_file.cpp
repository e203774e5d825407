// density_file: a df3 file's voxels in 8, 16 and 32 bits, without and with interpolation, against values POV-Ray
// 3.7 printed for the same files (function { pattern { density_file df3 "…" interpolate N } }), and the
// messages of a file that cannot be read.
#include <cstdint>
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/surface/density_file.hpp"
#include "raytrace/surface/patterns.hpp"
#include "temp_dir.hpp"

using namespace rt;

namespace {

const SourceLoc kAt{std::string("scene.pov"), 1, 1};

// A df3 file of 4×3×2 voxels whose 8-bit value is (60x + 7y + 3z) mod 256, each widened to `width` bytes as
// v·257 + 1 (16 bits) or v·16843009 + 5 (32 bits): the files POV-Ray read.
std::string df3(int width) {
  std::string s = {0, 4, 0, 3, 0, 2};
  for (int z = 0; z < 2; ++z) {
    for (int y = 0; y < 3; ++y) {
      for (int x = 0; x < 4; ++x) {
        const std::uint32_t v = std::uint32_t(60 * x + 7 * y + 3 * z) % 256;
        const std::uint32_t wide = width == 1 ? v : width == 2 ? v * 257 + 1 : v * 16843009u + 5;
        for (int b = width - 1; b >= 0; --b) s += char(wide >> (8 * b) & 0xff);
      }
    }
  }
  return s;
}

double valueAt(const std::string& path, int interpolation, const glm::dvec3& p) {
  PatternArgs a;
  a.densityFile = std::make_shared<const DensityGrid>(readDensityFile(path, kAt));
  a.densityInterpolation = interpolation;
  return makeDensityFile(a)->value(p);
}

const glm::dvec3 kPoints[] = {{0.1, 0.2, 0.3},   {0.3, 0.2, 0.3},    {0.55, 0.2, 0.3},
                              {0.8, 0.2, 0.3},   {0.95, 0.7, 0.9},   {0.3, 0.7, 0.3},
                              {0.62, 0.41, 0.77}, {-0.05, 0.5, 0.5}, {0.5, 1.0, 0.5}};

// POV-Ray's values at kPoints: 8 bits with interpolate 0, 1 and 2; 16 bits with 0; 32 bits with 1.
constexpr double kPovRay[][5] = {
    {0.000000000, 0.117647059, 0.049129426, 0.000015259, 0.117647060},
    {0.235294118, 0.305882353, 0.305129409, 0.235309377, 0.305882354},
    {0.470588235, 0.541176471, 0.555482328, 0.470603494, 0.541176472},
    {0.705882353, 0.588235294, 0.632658839, 0.705897612, 0.588235295},
    {0.772549020, 0.192941176, 0.149600029, 0.772564279, 0.192941178},
    {0.290196078, 0.338823529, 0.342352957, 0.290211337, 0.338823531},
    {0.509803922, 0.622705882, 0.680529594, 0.509819181, 0.622705884},
    {0, 0, 0, 0, 0},
    {0, 0, 0, 0, 0}};

}  // namespace

TEST_CASE("density_file: the voxel at a point, blended by 8 or 64 voxels, in 8, 16 and 32 bits, as POV-Ray gives",
          "[density_file]") {
  const test::TempDir dir;
  const std::string bits8 = dir.write("8.df3", df3(1)), bits16 = dir.write("16.df3", df3(2)),
                    bits32 = dir.write("32.df3", df3(4));
  for (size_t i = 0; i < std::size(kPoints); ++i) {
    INFO("point " << i);
    // POV-Ray prints 9 decimals; its cubic blend is summed in single precision.
    CHECK(valueAt(bits8, 0, kPoints[i]) == Approx(kPovRay[i][0]).margin(1e-9));
    CHECK(valueAt(bits8, 1, kPoints[i]) == Approx(kPovRay[i][1]).margin(1e-9));
    CHECK(valueAt(bits8, 2, kPoints[i]) == Approx(kPovRay[i][2]).margin(1e-7));
    CHECK(valueAt(bits16, 0, kPoints[i]) == Approx(kPovRay[i][3]).margin(1e-9));
    CHECK(valueAt(bits32, 1, kPoints[i]) == Approx(kPovRay[i][4]).margin(1e-9));
  }
}

TEST_CASE("density_file: the cubic blend's lobes below a lone peak are clamped at 0, as POV-Ray's are",
          "[density_file]") {
  const test::TempDir dir;
  // Eight voxels along x, all 0 but the fifth: the blend is the Catmull-Rom kernel about x = 0.5.
  const std::string peak = dir.write("peak.df3", std::string{0, 8, 0, 1, 0, 1, 0, 0, 0, 0, char(255), 0, 0, 0});
  CHECK(valueAt(peak, 2, {0.475, 0.5, 0.5}) == Approx(0.912));  // 1 − 2.5·0.2² + 1.5·0.2³
  CHECK(valueAt(peak, 2, {0.4, 0.5, 0.5}) == Approx(0.168));
  CHECK(valueAt(peak, 2, {0.35, 0.5, 0.5}) == 0);  // the kernel's −0.064
  // Seven voxels 10, 40, …, 190: the cubic's voxel before the first is (2⁶⁴ − 1) mod 7 = 1, whose 40 gives
  // POV-Ray's 16.06375 / 255 at x = 0.05 (the last voxel's 190 would give about 5).
  const std::string seven = dir.write("seven.df3", std::string{0, 7, 0, 1, 0, 1, 10, 40, 70, 100, char(130), char(160), char(190)});
  CHECK(valueAt(seven, 2, {0.05, 0.5, 0.5}) == Approx(16.063750245 / 255).margin(1e-8));
}

TEST_CASE("density_file: a file too short, too long or without a header is one located error", "[density_file]") {
  const test::TempDir dir;
  const auto failure = [&](const std::string& name, const std::string& bytes) {
    const std::string path = dir.write(name, bytes);
    try {
      readDensityFile(path, kAt);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(failure("short.df3", df3(1).substr(0, 20)) ==
        "scene.pov:1:1: error: the density file \"" + dir.file("short.df3") +
            "\" holds 14 bytes of voxels, which is not 1, 2 or 4 for each of its 4x3x2");
  // 65535³ voxels named by a file of 6 bytes of voxels: refused before anything is allocated.
  CHECK(failure("huge.df3", std::string{char(255), char(255), char(255), char(255), char(255), char(255), 1, 2, 3, 4, 5, 6}) ==
        "scene.pov:1:1: error: the density file \"" + dir.file("huge.df3") +
            "\" holds 6 bytes of voxels, which is not 1, 2 or 4 for each of its 65535x65535x65535");
  CHECK(failure("empty.df3", std::string{0, 0, 0, 4, 0, 4}) ==
        "scene.pov:1:1: error: the density file \"" + dir.file("empty.df3") + "\" has no voxels");
  CHECK(failure("cut.df3", std::string{0, 4, 0}) ==
        "scene.pov:1:1: error: the density file \"" + dir.file("cut.df3") + "\" has no df3 header");
}

TEST_CASE("density_file in a scene: its file found beside the scene, interpolate 0 to 2, and its errors",
          "[density_file]") {
  const test::TempDir dir;
  dir.write("v.df3", df3(1));
  const auto parse = [&](const std::string& body) {
    try {
      povray::parsePovRay("#version 3.7;\n" + body, dir.file("scene.pov"), povray::PovRayOptions{{}, 320, 240, false});
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(parse("plane { z, 0 pigment { density_file df3 \"v.df3\" interpolate 2 } }\n") == "no error");
  CHECK(parse("sphere { 0, 1 hollow pigment { rgbt 1 } interior { media { emission 1 density { density_file df3 "
              "\"v.df3\" interpolate 1 } } } }\n") == "no error");
  CHECK(parse("plane { z, 0 pigment { density_file df3 \"none.df3\" } }\n") ==
        dir.file("scene.pov") + ":2:41: error: cannot find the density file \"none.df3\"");
  CHECK(parse("plane { z, 0 pigment { density_file \"v.df3\" } }\n") ==
        dir.file("scene.pov") + ":2:24: error: 'density_file' needs 'df3' and a file name");
  CHECK(parse("plane { z, 0 pigment { density_file df3 \"v.df3\" interpolate 3 } }\n") ==
        dir.file("scene.pov") + ":2:49: error: the density_file's interpolate must be 0, 1 or 2");
}
