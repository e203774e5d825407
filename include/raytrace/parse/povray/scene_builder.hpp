// A POV-Ray 3.7 scene file read into a SceneDesc: the interpreter runs the language, and each scene statement
// it hands on becomes a camera, a light or an object, or is refused as "not supported yet".
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "raytrace/parse/povray/clock.hpp"
#include "raytrace/scene/description.hpp"

namespace rt::povray {

struct PovRayOptions {
  std::vector<std::string> libraryPaths;  // -L folders
  int imageWidth = 320, imageHeight = 240;
  bool debugOutput = true;  // #debug and #warning text to stderr
  std::vector<std::string> declares;  // "name=value", a number or else a string, as POV-Ray's Declare=
  size_t maxTokens = 0;               // InterpreterOptions::maxTokens
  std::string writeFolder;            // InterpreterOptions::writeFolder
  bool writeAnywhere = false;         // InterpreterOptions::writeAnywhere
  Clock clock;                        // InterpreterOptions::clock
};

SceneDesc parsePovRay(std::string_view text, const std::string& path, const PovRayOptions& options = {});

// Whether a .pov file is written in POV-Ray 3.7 rather than the course's subset: it uses a # directive or
// global_settings (docs/povray-language.md).
bool usesPovRayLanguage(std::string_view text);

}  // namespace rt::povray
