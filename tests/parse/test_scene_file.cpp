#include <random>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include "raytrace/app/commands.hpp"
#include "raytrace/util/limits.hpp"
#include "raytrace/parse/scene_file.hpp"
#include "temp_dir.hpp"

using namespace rt;

TEST_CASE("loader: the extension names the language, whatever the text looks like") {
  const std::string cli = "fov 60\n", pov = "camera { location <0,0,1> }\n";
  CHECK(sceneLanguage("a.cli", cli) == SceneLanguage::Cs3451);
  CHECK(sceneLanguage("a.CLI", pov) == SceneLanguage::Cs3451);
  CHECK(sceneLanguage("a.pov", cli) == SceneLanguage::Pov);
  CHECK(sceneLanguage("dir.cli/a.Pov", cli) == SceneLanguage::Pov);
}

TEST_CASE("loader: without a known extension the first meaningful line decides, POV by default") {
  CHECK(sceneLanguage("scene", "# colored lights\r\n\r\nfov 60\r\n") == SceneLanguage::Cs3451);
  CHECK(sceneLanguage("scene.txt", "sphere 0 0 -4 1\n") == SceneLanguage::Cs3451);
  CHECK(sceneLanguage("scene", "sphere { <0,0,-4>, 1 }\n") == SceneLanguage::Pov);
  CHECK(sceneLanguage("scene", "// POV\ncamera {}\n") == SceneLanguage::Pov);
  CHECK(sceneLanguage("scene", "") == SceneLanguage::Pov);
  CHECK(sceneLanguage("dir.cli/scene", "camera {}\n") == SceneLanguage::Pov);
}

namespace {

const std::string kCliScene = "fov 60\nsurface 0 0 0  .4 .5 .6  0 0 0  1 0\nsphere 0 0 -4 1\n";

}  // namespace

TEST_CASE("loader: loadScene parses each language by its extension or, without one, its text") {
  const test::TempDir dir;
  CHECK(loadScene(dir.write("a.cli", kCliScene)).language == SceneLanguage::Cs3451);
  CHECK(loadScene(dir.write("b", kCliScene)).language == SceneLanguage::Cs3451);
  const std::string pov = "camera { location <0,0,0> up <0,1,0> right <1,0,0> look_at <0,0,-1> }\n";
  CHECK(loadScene(dir.write("c", pov)).language == SceneLanguage::Pov);
  const std::string wrong = dir.write("d.pov", kCliScene);
  REQUIRE_THROWS_WITH(loadScene(wrong), wrong + ":1:1: error: unknown keyword 'fov'");
}

TEST_CASE("loader: the ray commands take a .cli scene") {
  const test::TempDir dir;
  std::ostringstream out, err;
  // Pixel (150, 149) of 300 × 300 is the course's row 150, which looks straight down −z (cs3451 §A.4.1).
  REQUIRE(runCommand({"firsthit", dir.write("s.cli", kCliScene), "300", "300", "150", "149"}, out, err) == 0);
  CHECK(out.str() ==
        "Pixel: [150, 149] Ray: {0.0000 0.0000 0.0000} -> {0.0000 0.0000 -1.0000}\n"
        "T = 3.0000\n"
        "Object Type: Sphere\n"
        "Color: 0.4000 0.5000 0.6000\n");
  CHECK(err.str().empty());
}

namespace {

std::string errorOf(const std::string& path) {
  try {
    loadScene(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("loader: readFile returns the bytes exactly, NUL bytes included") {
  const test::TempDir dir;
  const std::string bytes("a\0b\r\n\xFF", 6);
  CHECK(readFile(dir.write("x.pov", bytes)).view() == bytes);
}

// Pieces of 1 MiB read on several threads land where they belong: of random bytes, a piece out of place or
// a short one would not match.
TEST_CASE("loader: a file read on several threads is the same as read on one") {
  const test::TempDir dir;
  std::mt19937 rng(3);
  std::string bytes(3 * (size_t(1) << 20) + 12345, '\0');
  for (char& c : bytes) c = char(rng());
  const std::string path = dir.write("big.pov", bytes);
  for (const int threads : {1, 2, 3}) CHECK(readFile(path, threads).view() == bytes);
}

TEST_CASE("loader: files that are not scenes are refused with one reason") {
  const test::TempDir dir;
  const std::string missing = dir.file("missing.pov");
  CHECK(errorOf(missing) == "cannot open '" + missing + "': No such file or directory");

  const std::string folder = dir.file("folder.pov");
  REQUIRE(mkdir(folder.c_str(), 0755) == 0);
  CHECK(errorOf(folder) == "cannot read '" + folder + "': it is a directory, not a scene file");

  // A FIFO without a writer would block a plain open and never end a read.
  const std::string fifo = dir.file("fifo.pov");
  REQUIRE(mkfifo(fifo.c_str(), 0644) == 0);
  CHECK(errorOf(fifo) == "cannot read '" + fifo + "': it is not a regular file");
  CHECK(errorOf("/dev/zero") == "cannot read '/dev/zero': it is not a regular file");
}

TEST_CASE("loader: a file that vanishes before it is read is a missing file") {
  const test::TempDir dir;
  const std::string path = dir.write("gone.pov", "camera {}");
  REQUIRE(unlink(path.c_str()) == 0);
  CHECK(errorOf(path) == "cannot open '" + path + "': No such file or directory");
}

TEST_CASE("loader: a scene file over the size limit is refused before it is read") {
  const test::TempDir dir;
  const std::string path = dir.write("big.pov", "");
  REQUIRE(truncate(path.c_str(), off_t(kMaxSceneFileBytes + 1)) == 0);  // sparse: no disk used
  CHECK(errorOf(path) == "cannot read '" + path + "': it is larger than 1024 MiB, the most a scene file may have");
}

TEST_CASE("loader: empty and binary files are located parse errors") {
  const test::TempDir dir;
  const std::string empty = dir.write("empty.pov", "");
  CHECK(errorOf(empty) == empty + ":1:1: error: the scene has no camera");
  const std::string png = dir.write("image.pov", "\x89PNG\r\n\x1A\n");
  CHECK(errorOf(png) == png + ":1:1: error: unexpected byte 0x89 (is this a text scene file?)");
}
