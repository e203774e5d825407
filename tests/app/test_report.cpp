#include <sstream>

#include <catch2/catch.hpp>

#include "raytrace/parse/cs3451_parser.hpp"
#include "raytrace/app/report.hpp"

using namespace rt;

TEST_CASE("report: sceneinfo shows a .cli surface as its colours, power and reflection") {
  const SceneDesc s = parseCs3451("fov 60\nsurface .1 .2 .3  .4 .5 .6  .7 .8 .9  20 .5\nsphere 0 0 -4 1\n", "t.cli");
  std::ostringstream out;
  printSceneInfo(out, s);
  const std::string text = out.str();
  const std::string object = text.substr(text.find("Object[0]:"));
  CHECK(object ==
        "Object[0]:\n"
        "- Type: Sphere\n"
        "- Center: {0.0000 0.0000 -4.0000}\n"
        "- Radius: 1.0000\n"
        "- Material:\n"
        "  - Ambient: {0.1000 0.2000 0.3000}\n"
        "  - Diffuse: {0.4000 0.5000 0.6000}\n"
        "  - Specular: {0.7000 0.8000 0.9000}\n"
        "  - Power: 20.0000\n"
        "  - Reflection: 0.5000\n");
}
