// Test support: the error a course-dialect object gives when it is read, after a camera.
#pragma once

#include <string>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/util/error.hpp"

namespace rt::test {

// The message parsing `object` (line 2 of a scene called s.pov) stops with, or "" if it parses.
inline std::string messageOf(const std::string& object) {
  try {
    parsePov("camera { location <0,0,5> look_at <0,0,0> }\n" + object, "s.pov");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "";
}

}  // namespace rt::test
