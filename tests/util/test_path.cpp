#include <catch2/catch.hpp>

#include "raytrace/util/path.hpp"

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
