#include "raytrace/loader.hpp"

#include <string>

#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <unistd.h>

#include "raytrace/limits.hpp"
#include "temp_dir.hpp"

using rt::test::TempDir;

namespace {

std::string errorOf(const std::string& path) {
  try {
    rt::loadScene(path);
  } catch (const rt::Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("readFile returns the bytes exactly, NUL bytes included", "[loader]") {
  const TempDir dir;
  const std::string bytes("a\0b\r\n\xFF", 6);
  CHECK(rt::readFile(dir.write("x.pov", bytes)) == bytes);
}

TEST_CASE("files that are not scenes are refused with one reason", "[loader]") {
  const TempDir dir;
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

TEST_CASE("a file that vanishes before it is read is a missing file", "[loader]") {
  const TempDir dir;
  const std::string path = dir.write("gone.pov", "camera {}");
  REQUIRE(unlink(path.c_str()) == 0);
  CHECK(errorOf(path) == "cannot open '" + path + "': No such file or directory");
}

TEST_CASE("a scene file over the size limit is refused before it is read", "[loader]") {
  const TempDir dir;
  const std::string path = dir.write("big.pov", "");
  REQUIRE(truncate(path.c_str(), off_t(rt::kMaxSceneFileBytes + 1)) == 0);  // sparse: no disk used
  CHECK(errorOf(path) == "cannot read '" + path + "': it is larger than 1024 MiB, the most a scene file may have");
}

TEST_CASE("empty and binary files are located parse errors", "[loader]") {
  const TempDir dir;
  const std::string empty = dir.write("empty.pov", "");
  CHECK(errorOf(empty) == empty + ":1:1: error: the scene has no camera");
  const std::string png = dir.write("image.pov", "\x89PNG\r\n\x1A\n");
  CHECK(errorOf(png) == png + ":1:1: error: unexpected byte 0x89 (is this a text scene file?)");
}
