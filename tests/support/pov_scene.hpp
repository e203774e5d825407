// A POV-Ray 3.7 scene from a few lines, and the message a bad one stops with, for the shape tests.
#pragma once

#include <string>

#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/util/error.hpp"

namespace rt::test {

inline SceneDesc pov(const std::string& body) {
  return povray::parsePovRay("#version 3.7;\n" + body, "scene.pov", povray::PovRayOptions{{}, 320, 240, false});
}

// The whole message of the error the scene stops with, or "no error".
inline std::string povFailure(const std::string& body) {
  try {
    pov(body);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace rt::test
