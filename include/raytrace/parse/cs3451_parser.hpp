// The Georgia Tech CS 3451 (Spring 2018) Project 3 scene language, `.cli` files (docs/reference/cs3451.md §A.2):
// one command per line, run in order, each `write` rendering the scene built so far.
#pragma once

#include <string>
#include <string_view>

#include "raytrace/scene/description.hpp"

namespace rt {

// Parses a whole .cli text. The result is the scene as it stands at the end of the file, with one WriteDesc
// per `write` (the scene as it stood at that line) and the language's dialect (Dialect::cs3451()).
// Throws ParseError ("file:line:col: error: …") at the first problem, so nothing is rendered from a bad file.
SceneDesc parseCs3451(std::string_view text, const std::string& file);

// Whether a text whose file name says nothing reads as .cli: its first line that is neither blank nor a `#`
// comment starts with a .cli command and has no '{', which every POV-subset object and block needs.
bool looksLikeCs3451(std::string_view text);

}  // namespace rt
