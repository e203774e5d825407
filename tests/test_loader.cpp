#include <catch2/catch.hpp>

#include "raytrace/loader.hpp"

using namespace rt;

TEST_CASE("loader: extension is the lower-cased suffix of the file name only") {
  CHECK(extension("i1.cli") == "cli");
  CHECK(extension("dir/Scene.POV") == "pov");
  CHECK(extension("a.b/c.Png") == "png");
  CHECK(extension("a.d/scene") == "");
  CHECK(extension("scene") == "");
  CHECK(extension(".png") == "");
  CHECK(extension("out/.png") == "");
  CHECK(extension("x.") == "");
}

TEST_CASE("loader: the extension names the language, whatever the text looks like") {
  const std::string cli = "fov 60\n", pov = "camera { location <0,0,1> }\n";
  CHECK(sceneLanguage("a.cli", cli) == SceneLanguage::Cli);
  CHECK(sceneLanguage("a.CLI", pov) == SceneLanguage::Cli);
  CHECK(sceneLanguage("a.pov", cli) == SceneLanguage::Pov);
  CHECK(sceneLanguage("dir.cli/a.Pov", cli) == SceneLanguage::Pov);
}

TEST_CASE("loader: without a known extension the first meaningful line decides, POV by default") {
  CHECK(sceneLanguage("scene", "# colored lights\r\n\r\nfov 60\r\n") == SceneLanguage::Cli);
  CHECK(sceneLanguage("scene.txt", "sphere 0 0 -4 1\n") == SceneLanguage::Cli);
  CHECK(sceneLanguage("scene", "sphere { <0,0,-4>, 1 }\n") == SceneLanguage::Pov);
  CHECK(sceneLanguage("scene", "// POV\ncamera {}\n") == SceneLanguage::Pov);
  CHECK(sceneLanguage("scene", "") == SceneLanguage::Pov);
  CHECK(sceneLanguage("dir.cli/scene", "camera {}\n") == SceneLanguage::Pov);
}
