// Reading a scene file from disk in whichever language it is written.
#pragma once

#include <string>

#include "raytrace/scene_desc.hpp"

namespace rt {

// The whole file as bytes. Throws Error with a one-line reason for a missing, unreadable or non-regular file.
std::string readFile(const std::string& path);

// Reads and parses a scene. The language comes from the extension (.pov); otherwise the POV subset is assumed.
SceneDesc loadScene(const std::string& path);

}  // namespace rt
