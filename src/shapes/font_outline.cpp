#include "raytrace/shapes/font_outline.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

// The library and the face, released however the reading ends.
struct FontFile {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  ~FontFile() {
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }
};

// Turns the segments FT_Outline_Decompose walks into edges, in ems, placed at the pen.
struct Flattener {
  double scale;       // ems per font unit
  double fill;        // +1 when the font fills right of its contours (TrueType), -1 when left (PostScript)
  glm::dvec2 pen;
  std::vector<OutlineEdge>& edges;
  glm::dvec2 last{0};  // where the contour has got to

  glm::dvec2 point(const FT_Vector* v) const { return pen + scale * glm::dvec2(double(v->x), double(v->y)); }

  // The outward unit normal where the contour runs along `tangent`; along `chord` where the tangent vanishes
  // (a control point on its end point).
  glm::dvec2 outward(glm::dvec2 tangent, glm::dvec2 chord) const {
    if (glm::length(tangent) < 1e-12) tangent = chord;
    return fill * glm::normalize(glm::dvec2(-tangent.y, tangent.x));
  }

  void line(glm::dvec2 to) {
    if (to == last) return;
    const glm::dvec2 n = outward(to - last, to - last);
    edges.push_back({last, to, n, n});
    last = to;
  }

  // A curve given by its point and tangent at s in [0, 1], whose second derivative is at most `bend` long:
  // a chord over a step h strays at most bend·h²/8 from it, so that many pieces keep within the tolerance.
  // The count is capped so that a malformed font cannot ask for millions.
  template <class Point, class Tangent> void curve(double bend, Point at, Tangent tangent) {
    const int pieces = std::clamp(int(std::ceil(std::sqrt(bend / (8 * kOutlineTolerance)))), 1, 1024);
    for (int i = 0; i < pieces; ++i) {
      const double s0 = double(i) / pieces, s1 = double(i + 1) / pieces;
      const glm::dvec2 from = last, to = at(s1);
      if (to == from) continue;
      edges.push_back({from, to, outward(tangent(s0), to - from), outward(tangent(s1), to - from)});
      last = to;
    }
  }
};

int moveTo(const FT_Vector* to, void* user) {
  auto& f = *static_cast<Flattener*>(user);
  f.last = f.point(to);
  return 0;
}

int lineTo(const FT_Vector* to, void* user) {
  auto& f = *static_cast<Flattener*>(user);
  f.line(f.point(to));
  return 0;
}

int conicTo(const FT_Vector* control, const FT_Vector* to, void* user) {
  auto& f = *static_cast<Flattener*>(user);
  const glm::dvec2 p0 = f.last, c = f.point(control), p2 = f.point(to);
  f.curve(
      2 * glm::length(p0 - 2.0 * c + p2),
      [&](double s) { return (1 - s) * (1 - s) * p0 + 2 * s * (1 - s) * c + s * s * p2; },
      [&](double s) { return 2 * (1 - s) * (c - p0) + 2 * s * (p2 - c); });
  return 0;
}

int cubicTo(const FT_Vector* control1, const FT_Vector* control2, const FT_Vector* to, void* user) {
  auto& f = *static_cast<Flattener*>(user);
  const glm::dvec2 p0 = f.last, c1 = f.point(control1), c2 = f.point(control2), p3 = f.point(to);
  f.curve(
      6 * std::max(glm::length(p0 - 2.0 * c1 + c2), glm::length(c1 - 2.0 * c2 + p3)),
      [&](double s) {
        const double r = 1 - s;
        return r * r * r * p0 + 3 * s * r * r * c1 + 3 * s * s * r * c2 + s * s * s * p3;
      },
      [&](double s) {
        const double r = 1 - s;
        return 3 * r * r * (c1 - p0) + 6 * s * r * (c2 - c1) + 3 * s * s * (p3 - c2);
      });
  return 0;
}

// The code points of UTF-8 text; a byte that starts no valid sequence stands for itself.
std::vector<char32_t> codePoints(const std::string& text) {
  std::vector<char32_t> out;
  for (size_t i = 0; i < text.size();) {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b = byte(i);
    const size_t length = b < 0x80 ? 1 : (b >> 5) == 6 ? 2 : (b >> 4) == 14 ? 3 : (b >> 3) == 30 ? 4 : 0;
    char32_t c = length == 1 ? b : b & (0x7f >> length);
    bool valid = length > 0 && i + length <= text.size();
    for (size_t k = 1; valid && k < length; ++k) {
      valid = (byte(i + k) & 0xc0) == 0x80;
      c = (c << 6) | (byte(i + k) & 0x3f);
    }
    out.push_back(valid ? c : b);
    i += valid ? length : 1;
  }
  return out;
}

}  // namespace

std::vector<PlacedGlyph> textOutline(const std::string& fontPath, const std::string& text, const glm::dvec2& offset,
                                     const SourceLoc& at) {
  FontFile font;
  if (FT_Init_FreeType(&font.library)) throw ParseError(at, "cannot start FreeType to read the font");
  if (FT_New_Face(font.library, fontPath.c_str(), 0, &font.face) || !FT_IS_SCALABLE(font.face)) {
    throw ParseError(at, "cannot read the font file " + quote(fontPath));
  }
  FT_Face face = font.face;
  // Unicode when the font has it, else its first character map: povlogo.ttf has only a Macintosh one and a
  // symbol one, and its logo is 'P' in the first.
  if (FT_Select_Charmap(face, FT_ENCODING_UNICODE) && face->num_charmaps > 0) FT_Set_Charmap(face, face->charmaps[0]);
  const double scale = 1.0 / face->units_per_EM;
  const FT_Outline_Funcs walk{moveTo, lineTo, conicTo, cubicTo, 0, 0};

  std::vector<PlacedGlyph> glyphs;
  glm::dvec2 pen(0);
  FT_UInt previous = 0;
  bool first = true;
  for (const char32_t c : codePoints(text)) {
    const FT_UInt index = FT_Get_Char_Index(face, c);
    FT_Vector kern{0, 0};
    if (previous && index && !FT_Get_Kerning(face, previous, index, FT_KERNING_UNSCALED, &kern)) {
      pen.x += scale * double(kern.x);
    }
    if (FT_Load_Glyph(face, index, FT_LOAD_NO_SCALE) || face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) {
      throw ParseError(at, "cannot read a glyph of the font file " + quote(fontPath));
    }
    // As POV-Ray: the first character's left side bearing is taken off, so that its left edge is at x = 0.
    if (first) pen.x = -scale * double(face->glyph->metrics.horiBearingX);
    first = false;
    PlacedGlyph g;
    FT_Outline& outline = face->glyph->outline;
    Flattener f{scale, FT_Outline_Get_Orientation(&outline) == FT_ORIENTATION_POSTSCRIPT ? -1.0 : 1.0,
                pen, g.edges};
    if (FT_Outline_Decompose(&outline, &walk, &f)) {
      throw ParseError(at, "cannot read a glyph of the font file " + quote(fontPath));
    }
    if (!g.edges.empty()) {
      g.lo = g.hi = g.edges.front().a;
      for (const OutlineEdge& e : g.edges) {
        g.lo = glm::min(g.lo, glm::min(e.a, e.b));
        g.hi = glm::max(g.hi, glm::max(e.a, e.b));
      }
      glyphs.push_back(std::move(g));
    }
    pen += glm::dvec2(scale * double(face->glyph->advance.x), 0) + offset;
    previous = index;
  }
  return glyphs;
}

}  // namespace rt
