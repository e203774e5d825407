#include <catch2/catch.hpp>

#include "raytrace/util/path.hpp"

#include <unistd.h>

#include "temp_dir.hpp"

using namespace rt;

TEST_CASE("path: extension is the lower-cased suffix of the file name only") {
  CHECK(extension("i1.cli") == "cli");
  CHECK(extension("dir/Scene.POV") == "pov");
  CHECK(extension("a.b/c.Png") == "png");
  CHECK(extension("a.d/scene") == "");
  CHECK(extension("scene") == "");
  CHECK(extension(".png") == "");
  CHECK(extension("out/.png") == "");
  CHECK(extension("x.") == "");
}

TEST_CASE("path: sameFile is one file under any name, and never a missing one") {
  const rt::test::TempDir dir;
  const std::string a = dir.write("a", "x"), b = dir.write("b", "x");
  REQUIRE(link(a.c_str(), dir.file("hard").c_str()) == 0);
  REQUIRE(symlink(a.c_str(), dir.file("soft").c_str()) == 0);
  CHECK(sameFile(a, a));
  CHECK(sameFile(a, dir.file("./a")));
  CHECK(sameFile(a, dir.file("hard")));
  CHECK(sameFile(dir.file("soft"), a));
  CHECK_FALSE(sameFile(a, b));
  CHECK_FALSE(sameFile(dir.file("missing"), dir.file("missing")));
}
