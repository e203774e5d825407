// A string's glyph outlines from a TrueType font (FreeType), as straight edges in em units: what the `text`
// shape (shapes/text.hpp) extrudes.
#pragma once

#include <string>
#include <vector>

#include "raytrace/geometry/math.hpp"
#include "raytrace/util/error.hpp"

namespace rt {

// One straight piece of a closed contour, flattened from the font's curves to within kOutlineTolerance, in
// the font's direction. It carries the outward unit normals of the true curve at its ends, so that a curved
// wall is shaded smoothly rather than in facets.
struct OutlineEdge {
  glm::dvec2 a, b;
  glm::dvec2 normalA, normalB;
};

// One character of the string where it stands: its contours' edges and their 2-D bounds.
struct PlacedGlyph {
  std::vector<OutlineEdge> edges;
  glm::dvec2 lo{0}, hi{0};
};

constexpr double kOutlineTolerance = 1e-4;  // the largest distance of an edge from its curve, in ems

// The glyphs of `text` (UTF-8) in the font file at `fontPath`, one em to a unit, on the baseline y = 0. As in
// POV-Ray, the first character's left edge is at x = 0, each next one follows after the previous one's
// advance, the font's kerning and `offset`, and a character the font lacks is drawn as the font's missing
// glyph (mostly a box). Blanks are advances alone and are left out. Throws ParseError at `at` when the file is
// not a font FreeType reads.
std::vector<PlacedGlyph> textOutline(const std::string& fontPath, const std::string& text, const glm::dvec2& offset,
                                     const SourceLoc& at);

}  // namespace rt
