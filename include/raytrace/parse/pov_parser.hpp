// The POV-Ray subset of the Cal Poly CSC 473 course (docs/reference/csc473.md §b), read as POV-Ray 3.7 reads it.
#pragma once

#include <string>
#include <string_view>

#include "raytrace/scene/description.hpp"

namespace rt {

// Parses a whole .pov text. Throws ParseError ("file:line:col: error: …") at the first problem. A large text
// is read in parts on up to `threads` threads; the result is the same for any number.
SceneDesc parsePov(std::string_view text, const std::string& file, int threads = 1);

}  // namespace rt
