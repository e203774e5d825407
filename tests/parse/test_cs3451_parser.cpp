#include <cmath>
#include <random>
#include <sstream>

#include <catch2/catch.hpp>
#include <stb/stb_image.h>

#include "raytrace/render/camera.hpp"
#include "raytrace/app/commands.hpp"
#include "raytrace/parse/cs3451_parser.hpp"
#include "temp_dir.hpp"

using namespace rt;
using namespace std::string_literals;

namespace {

SceneDesc parse(const std::string& text) { return parseCs3451(text, "t.cli"); }

const std::string kKnown = " (the commands are fov, background, light, surface, sphere, cylinder, write)";
const std::string kHeader = "fov 60\nsurface .1 .2 .3  .4 .5 .6  .7 .8 .9  20 .5\n";

}  // namespace

TEST_CASE("cs3451_parser: fov gives the course camera at the origin looking down -z (cs3451 A.4.1)") {
  const SceneDesc s = parse("fov 90\n");
  const CameraDesc& c = s.camera;
  CHECK(c.location == glm::dvec3(0));
  CHECK(c.lookAt == glm::dvec3(0, 0, -1));
  // k = tan(45°) = 1: the image plane at z = −1 spans ±1.
  CHECK(c.up.y == Approx(2.0));
  CHECK(c.right.x == Approx(2.0));
  CHECK(c.up.x == 0);
  CHECK(c.right.y == 0);
  CHECK(c.pixelOffset == glm::dvec2(0, 1));
  CHECK(c.rightFollowsImage);
}

TEST_CASE("cs3451_parser: pixel rays follow x = (i - W/2)2k/W, y = -(j - H/2)2k/H with no half-pixel offset") {
  const SceneDesc s = parse("fov 60\n");
  const double k = std::tan(glm::radians(30.0));
  const int w = 300, h = 300;
  const Camera<double> camera(s.camera, w, h);
  std::mt19937 rng(3451);
  std::uniform_int_distribution<int> col(0, w - 1), row(0, h - 1);
  for (int n = 0; n < 200; ++n) {
    const int i = col(rng), j = row(rng);  // j counts rows from the top, as the course's loops do
    CAPTURE(i, j);
    const glm::dvec3 d = camera.pixelRay(i, h - 1 - j).dir;
    const glm::dvec3 want = glm::normalize(glm::dvec3((i - w / 2.0) * 2 * k / w, -(j - h / 2.0) * 2 * k / h, -1));
    CHECK(d.x == Approx(want.x).margin(1e-12));
    CHECK(d.y == Approx(want.y).margin(1e-12));
    CHECK(d.z == Approx(want.z).margin(1e-12));
  }
  // The centre pixel (150, 150) looks exactly down −z.
  CHECK(camera.pixelRay(150, h - 1 - 150).dir == glm::dvec3(0, 0, -1));
}

TEST_CASE("cs3451_parser: a wide image keeps fov vertical and its pixels square") {
  const SceneDesc s = parse("fov 90\n");
  const Camera<double> camera(s.camera, 600, 300);
  // Top-left pixel: x spans ±2 (twice the height's ±1), y = 1.
  const glm::dvec3 d = camera.pixelRay(0, 299).dir;
  const glm::dvec3 want = glm::normalize(glm::dvec3(-2, 1, -1));
  CHECK(d.x == Approx(want.x).margin(1e-15));
  CHECK(d.y == Approx(want.y).margin(1e-15));
  CHECK(d.z == Approx(want.z).margin(1e-15));
}

TEST_CASE("cs3451_parser: every command, in the course's argument orders (cs3451 A.2)") {
  const SceneDesc s = parse(
      "fov 60\n"
      "background .2 .3 1\n"
      "light .7 .6 .5  4 3 8\n"
      "surface .1 .2 .3  .4 .5 .6  .7 .8 .9  20 .5\n"
      "sphere -1.5 1 -6 .75\n"
      "cylinder 2  1.5 -6  -2.5 -0.5\n"
      "write out.png\n");
  CHECK(s.language == SceneLanguage::Cs3451);
  CHECK(s.file == "t.cli");
  CHECK(s.background == Color(.2f, .3f, 1));
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].color == Color(.7f, .6f, .5f));  // colour first,
  CHECK(s.lights[0].position == glm::dvec3(4, 3, 8));  // then position

  REQUIRE(s.objects.size() == 2);
  const auto& sphere = std::get<SphereDesc>(s.objects[0].shape);
  CHECK(sphere.center == glm::dvec3(-1.5, 1, -6));  // centre first, radius last
  CHECK(sphere.radius == .75);
  CHECK(s.objects[0].loc.str() == "t.cli:5:1");
  const auto& cyl = std::get<CylinderDesc>(s.objects[1].shape);  // radius x z ymin ymax: vertical, capped
  CHECK(cyl.base == glm::dvec3(1.5, -2.5, -6));
  CHECK(cyl.cap == glm::dvec3(1.5, -0.5, -6));
  CHECK(cyl.radius == 2);

  const Material& m = s.objects[1].material;  // ambient, diffuse, specular, P, Krefl
  CHECK(m.ambient == Color(.1f, .2f, .3f));
  CHECK(m.diffuse == Color(.4f, .5f, .6f));
  CHECK(m.specular == Color(.7f, .8f, .9f));
  CHECK(m.exponent == 20);
  CHECK(m.reflection == .5f);
  CHECK(m.pigment == m.diffuse);

  REQUIRE(s.writes.size() == 1);
  CHECK(s.writes[0].path == "out.png");
  CHECK(s.writes[0].loc.str() == "t.cli:7:1");
  CHECK(sceneAt(s, s.writes[0]).objects.size() == 2);
  CHECK(sceneAt(s, s.writes[0]).writes.empty());
}

TEST_CASE("cs3451_parser: every scene has the language's dialect (cs3451 A.4)") {
  const SceneDesc s = parse("fov 60\n");
  CHECK(s.background == Color(0));  // the starter's background(0,0,0)
  CHECK(s.dialect.toByte() == Dialect::ToByte::Truncate);
  CHECK(s.dialect.bounced(Color(2, 0.5f, -1)) == Color(1, 0.5f, 0));
  CHECK_FALSE(s.dialect.reflectionReplacesLocal());
  CHECK(s.dialect.reflectionTint(Color(0.5f)) == Color(1));
  CHECK(s.maxDepth() == 9);
  CHECK_FALSE(s.dialect.shadesAtDepthLimit());
}

TEST_CASE("cs3451_parser: commands run in order; each write keeps the scene as it stood") {
  const SceneDesc s = parse(kHeader +
                            "sphere 0 0 -4 1\n"
                            "write a.png\n"
                            "fov 90\n"
                            "background 1 0 0\n"
                            "light 1 1 1  0 5 0\n"
                            "surface 0 0 0  1 1 1  0 0 0  1 0\n"
                            "sphere 0 0 -8 1\n"
                            "write b.PNG\n");
  REQUIRE(s.writes.size() == 2);
  const SceneDesc a = sceneAt(s, s.writes[0]);
  CHECK(a.objects.size() == 1);
  CHECK(a.lights.empty());
  CHECK(a.background == Color(0));
  CHECK(a.camera.up.y == Approx(2 * std::tan(glm::radians(30.0))));
  const SceneDesc b = sceneAt(s, s.writes[1]);
  CHECK(s.writes[1].path == "b.PNG");
  CHECK(b.objects.size() == 2);
  CHECK(b.lights.size() == 1);
  CHECK(b.background == Color(1, 0, 0));
  CHECK(b.camera.up.y == Approx(2.0));
  // A surface applies to the objects after it only.
  CHECK(b.objects[0].material.diffuse == Color(.4f, .5f, .6f));
  CHECK(b.objects[1].material.diffuse == Color(1));
  // The scene itself is the state at the end of the file.
  CHECK(s.objects.size() == 2);
}

// Each write records where the scene stood, not a copy of it: 2,000 writes of a 1,000-object scene keep 2,000
// counts, not two million objects (the memory a .cli file takes is proportional to its scene).
TEST_CASE("cs3451_parser: a write keeps counts, not a copy of the scene") {
  std::string text = kHeader;
  for (int i = 0; i < 1000; ++i) text += "sphere 0 0 -4 1\nwrite a.png\nwrite b.png\n";
  const SceneDesc s = parse(text);
  REQUIRE(s.writes.size() == 2000);
  CHECK(s.writes[1999].objects == 1000);
  CHECK(s.writes[0].objects == 1);
  CHECK(sceneAt(s, s.writes[1234]).objects.size() == 618);
}

TEST_CASE("cs3451_parser: CRLF, comments, blank lines, tabs and number spellings") {
  const SceneDesc s = parse(
      "# a comment\r\n"
      "\r\n"
      "   \t\r\n"
      "  fov\t60  # the rest of a line after '#' is a comment too\r\n"
      "surface .1 +.2 3.  -0 1e-1 1E+1  0 0 0  1 0\r\n"
      "\tsphere 0 0 -4 1\r\n"
      "#sphere 0 0 -4 1\r\n"
      "write x.png");  // no final newline
  REQUIRE(s.objects.size() == 1);
  CHECK(s.objects[0].loc.str() == "t.cli:6:2");
  const Material& m = s.objects[0].material;
  CHECK(m.ambient == Color(.1f, .2f, 3));
  CHECK(m.diffuse == Color(0, .1f, 10));
  REQUIRE(s.writes.size() == 1);
  CHECK(s.writes[0].path == "x.png");
}

TEST_CASE("cs3451_parser: a file without objects or writes is a valid, empty scene") {
  const SceneDesc s = parse("fov 45\n");
  CHECK(s.objects.empty());
  CHECK(s.lights.empty());
  CHECK(s.writes.empty());
}

TEST_CASE("cs3451_parser: errors are located and whole") {
  const auto error = [](const std::string& text, const std::string& message) {
    CAPTURE(text);
    REQUIRE_THROWS_WITH(parse(text), message);
  };
  SECTION("unknown commands") {
    error("fov 60\ntriangle 0 0 0\n", "t.cli:2:1: error: unknown command 'triangle'" + kKnown);
    error("FOV 60\n", "t.cli:1:1: error: unknown command 'FOV'" + kKnown);
    error("fov 60\n  eye 0 0 0\n", "t.cli:2:3: error: unknown command 'eye'" + kKnown);
  }
  SECTION("argument counts") {
    error(kHeader + "cylinder 1 1.5 -6 -2.5\n", "t.cli:3:1: error: 'cylinder' needs 5 numbers, found 4");
    error(kHeader + "sphere 0 0 -4 1 2\n", "t.cli:3:1: error: 'sphere' needs 4 numbers, found 5");
    error("fov\n", "t.cli:1:1: error: 'fov' needs 1 number, found 0");
    error("fov 60\nbackground 1 1\n", "t.cli:2:1: error: 'background' needs 3 numbers, found 2");
    error("fov 60\nlight 1 1 1 0 0\n", "t.cli:2:1: error: 'light' needs 6 numbers, found 5");
    error("fov 60\nsurface 0 0 0 1 1 1 0 0 0 1\n", "t.cli:2:1: error: 'surface' needs 11 numbers, found 10");
  }
  SECTION("values that are not numbers") {
    error(kHeader + "sphere 0 0 abc 1\n", "t.cli:3:12: error: 'sphere' takes numbers, found 'abc'");
    error("fov 60\nlight 1 1 1 0 0 0x10\n", "t.cli:2:17: error: 'light' takes numbers, found '0x10'");
    error("fov nan\n", "t.cli:1:5: error: 'fov' takes numbers, found 'nan'");
    error("fov 60\nbackground inf 0 0\n", "t.cli:2:12: error: 'background' takes numbers, found 'inf'");
    error("fov 60\nbackground 1e 0 0\n", "t.cli:2:12: error: 'background' takes numbers, found '1e'");
    error("fov 60\nbackground 1,0,0\n", "t.cli:2:12: error: 'background' takes numbers, found '1,0,0'");
    error("fov 1e999\n", "t.cli:1:5: error: number '1e999' is out of range");
  }
  SECTION("impossible values") {
    error(kHeader + "sphere 0 0 -4 -1\n", "t.cli:3:15: error: 'sphere' radius must be greater than 0, found -1");
    error(kHeader + "sphere 0 0 -4 0\n", "t.cli:3:15: error: 'sphere' radius must be greater than 0, found 0");
    error(kHeader + "cylinder -.5 0 -4 0 1\n",
          "t.cli:3:10: error: 'cylinder' radius must be greater than 0, found -.5");
    error(kHeader + "cylinder 1 0 -4 2 1\n",
          "t.cli:3:17: error: 'cylinder' ymin must be less than ymax, found ymin 2 and ymax 1");
    error(kHeader + "cylinder 1 0 -4 1 1\n",
          "t.cli:3:17: error: 'cylinder' ymin must be less than ymax, found ymin 1 and ymax 1");
    error("fov 180\n", "t.cli:1:5: error: 'fov' must be between 0 and 180 degrees, found 180");
    error("fov 0\n", "t.cli:1:5: error: 'fov' must be between 0 and 180 degrees, found 0");
    error("fov 60\nsurface 0 0 0 1 1 1 0 0 0 -2 0\n",
          "t.cli:2:27: error: 'surface' power P must not be negative, found -2");
  }
  SECTION("write") {
    error("fov 60\nwrite\n", "t.cli:2:1: error: 'write' needs a file name");
    error("fov 60\nwrite my image.png\n", "t.cli:2:10: error: 'write' takes one file name, found another word 'image.png'");
    error("fov 60\nwrite i1.jpg\n",
          "t.cli:2:7: error: 'write' makes PNG files: the name must end in .png, found 'i1.jpg'");
    error("fov 60\nwrite i1\n", "t.cli:2:7: error: 'write' makes PNG files: the name must end in .png, found 'i1'");
    error("fov 60\nwrite out/.png\n",
          "t.cli:2:7: error: 'write' makes PNG files: the name must end in .png, found 'out/.png'");
    error("write i1.png\nfov 60\n", "t.cli:1:1: error: 'write' comes before any 'fov', so there is no camera");
  }
  SECTION("what the file lacks") {
    error("fov 60\nsphere 0 0 -4 1\n", "t.cli:2:1: error: 'sphere' comes before any 'surface', so it has no material");
    error("fov 60\ncylinder 1 0 -4 0 1\n",
          "t.cli:2:1: error: 'cylinder' comes before any 'surface', so it has no material");
    error("# only a comment\n", "t.cli:2:1: error: the scene has no 'fov'");
    error("background 0 0 0", "t.cli:1:17: error: the scene has no 'fov'");
    error("", "t.cli:1:1: error: the scene has no 'fov'");
  }
  SECTION("binary files") {
    error("fov 60\nsph\x01re\n", "t.cli:2:4: error: unexpected byte 0x01 (is this a text scene file?)");
    error("fov 60\n# \0 in a comment\n"s, "t.cli:2:3: error: unexpected byte 0x00 (is this a text scene file?)");
  }
}

TEST_CASE("cs3451_parser: looksLikeCs3451 reads the first line that is not blank or a comment") {
  CHECK(looksLikeCs3451("fov 60\n"));
  CHECK(looksLikeCs3451("# colored lights\r\n\r\nfov 60\r\n"));
  CHECK(looksLikeCs3451("  \n\tsphere 0 0 -4 1\n"));
  CHECK(looksLikeCs3451("write x.png"));
  CHECK_FALSE(looksLikeCs3451("sphere { <0,0,0>, 1 }\n"));
  CHECK_FALSE(looksLikeCs3451("background { color rgb <0,0,0> }\n"));
  CHECK_FALSE(looksLikeCs3451("// a POV comment\nfov 60\n"));
  CHECK_FALSE(looksLikeCs3451("camera {\n"));
  CHECK_FALSE(looksLikeCs3451("fovea 60\n"));
  CHECK_FALSE(looksLikeCs3451("# just a comment\n"));
  CHECK_FALSE(looksLikeCs3451(""));
}

namespace {

struct Png {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // top row first
  glm::ivec3 at(int col, int row) const {
    const size_t i = (size_t(row) * width + col) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

Png readPng(const std::string& path) {
  Png png;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
  REQUIRE(data);
  png.rgb.assign(data, data + size_t(png.width) * png.height * 3);
  stbi_image_free(data);
  return png;
}

}  // namespace

TEST_CASE("cs3451_parser: render makes each write's PNG from the scene as it stood, in truncated bytes") {
  const test::TempDir dir;
  const std::string scene = dir.write("s.cli",
                                      "fov 90\n"
                                      "background .2 .5 .8\n"
                                      "surface .3 .6 .9  0 0 0  0 0 0  1 0\n"
                                      "write " + dir.file("empty.png") + "\n"
                                      "sphere 0 0 -3 2\n"
                                      "write " + dir.file("sphere.png") + "\n");
  std::ostringstream out, err;
  REQUIRE(runCommand({"render", scene, "3", "3", "--allow-write-anywhere"}, out, err) == 0);
  CHECK(dir.names() == std::vector<std::string>{"empty.png", "s.cli", "sphere.png"});  // no output.png
  // Truncation, not rounding (cs3451 §A.4.2): .2 .5 .8 → 51 127 204 and .3 .6 .9 → 76 153 229.
  const Png empty = readPng(dir.file("empty.png"));
  REQUIRE(empty.width == 3);
  REQUIRE(empty.height == 3);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) CHECK(empty.at(col, row) == glm::ivec3(51, 127, 204));
  }
  // With no light the sphere shows its ambient colour alone. The centre pixel looks along (−1/3, 1/3, −1),
  // 1.28 from the centre; the corner pixel along (−1, −1/3, −1), 2.18 from it.
  const Png sphere = readPng(dir.file("sphere.png"));
  CHECK(sphere.at(1, 1) == glm::ivec3(76, 153, 229));
  CHECK(sphere.at(0, 2) == glm::ivec3(51, 127, 204));
}

TEST_CASE("cs3451_parser: render without a size makes the course's 300 x 300 image") {
  const test::TempDir dir;
  const std::string scene = dir.write("s.cli", "fov 60\nwrite " + dir.file("out.png") + "\n");
  std::ostringstream out, err;
  REQUIRE(runCommand({"render", scene, "--allow-write-anywhere"}, out, err) == 0);
  const Png png = readPng(dir.file("out.png"));
  CHECK(png.width == 300);
  CHECK(png.height == 300);
}
