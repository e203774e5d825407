#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/shapes/font_outline.hpp"
#include "raytrace/shapes/kind.hpp"
#include "raytrace/shapes/object.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

template <class T> class Text;

// What a file says of a text: `text { ttf "font.ttf" "string" thickness, offset }`, or `internal N` for the
// font (POV-Ray 3.7's built-in fonts, which are the four files of Debian's fonts-povray). The font is read
// here, where a missing one can be told at its place in the file.
struct TextDesc {
  // As written, for sceneinfo; held apart, so that every object's shape stays as small as a triangle's.
  struct Written {
    std::string font;  // the file, where it was found
    std::string text;
    glm::dvec3 offset;  // added to the advance after every character, but for its z (as POV-Ray)
  };
  std::shared_ptr<const Written> written;
  double thickness;
  std::shared_ptr<const std::vector<PlacedGlyph>> glyphs;

  static bool named(std::string_view word) { return word == "text"; }
  static const char* name() { return "Text"; }
  static constexpr bool kFloatErrorBound = false;

  template <class Reader> static TextDesc read(Reader& r, std::string_view) {
    TextDesc d;
    const bool internal = r.keyword("internal");
    if (!internal && !r.keyword("ttf")) {
      throw ParseError(r.here(), "'text' needs ttf and a font file name, or internal and a font number");
    }
    const SourceLoc at = r.here();  // the font's name or number, where a font found nowhere is told
    std::string file;
    if (internal) {
      // POV-Ray truncates the number and takes any other than 0 to 3 for 0.
      static constexpr const char* kInternal[] = {"povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf"};
      const double n = r.number("the internal font number");
      file = kInternal[n > -1 && n < 4 ? int(n) : 0];
    } else {
      file = r.string("the font file name");
    }
    Written w;
    w.text = r.string("the text");
    d.thickness = r.positive("the text thickness");
    r.comma("after the text thickness");
    w.offset = r.vec3("the text offset");
    w.font = r.findFont(file);
    if (w.font.empty()) throw ParseError(at, "cannot find the font file " + quote(file));
    d.glyphs = std::make_shared<const std::vector<PlacedGlyph>>(textOutline(w.font, w.text, glm::dvec2(w.offset), at));
    d.written = std::make_shared<const Written>(std::move(w));
    return d;
  }
  // The thinner of the slab and the narrowest glyph.
  double smallestFeature() const {
    double least = glyphs->empty() ? std::numeric_limits<double>::infinity() : thickness;
    for (const PlacedGlyph& g : *glyphs) least = std::min({least, g.hi.x - g.lo.x, g.hi.y - g.lo.y});
    return least;
  }
  Ball boundingBall() const {
    const Aabb<double> b = bounds();
    return {(b.min + b.max) / 2.0, glm::length(b.max - b.min) / 2};
  }
  FlatFaces flatFaces() const { return {}; }  // computed in double (kFloatErrorBound): no offset to check
  void describe(std::ostream& out) const {
    out << "- Font: " << quote(written->font) << "\n- Text: " << quote(written->text)
        << "\n- Thickness: " << fixed4(thickness) << "\n- Offset: " << braces(written->offset) << "\n";
  }
  // The glyphs' boxes together, from z = 0 to the thickness; a point at the origin when nothing is drawn.
  Aabb<double> bounds() const {
    Aabb<double> b;
    for (const PlacedGlyph& g : *glyphs) {
      b.expand(glm::dvec3(g.lo, 0));
      b.expand(glm::dvec3(g.hi, thickness));
    }
    return glyphs->empty() ? Aabb<double>{glm::dvec3(0), glm::dvec3(0)} : b;
  }
  template <class T> std::unique_ptr<Object<T>> make(const ObjectBuild& b) const {
    return std::make_unique<Text<T>>(*this, b.material, b.id);
  }
};

// The glyphs' outlines extruded along z by the thickness: flat faces at both ends, where a point is inside by
// the non-zero winding rule as in TrueType, and walls along every edge. The glyphs are sorted into columns
// along x and each glyph's edges into bands along y, so that a ray meets only the glyphs of the columns it
// crosses, and in a glyph whose box it meets only the edges of the bands it crosses. Computed in double
// whatever T is.
template <class T> class Text final : public Object<T> {
 public:
  Text(const TextDesc& desc, const Material& material, int id);

  std::optional<Hit<T>> intersect(const Ray<T>& ray, Interval<T> range) const override;
  std::optional<Aabb<T>> bounds() const override { return Aabb<T>{Vec3<T>(bounds_.min), Vec3<T>(bounds_.max)}; }
  bool inside(const Vec3<T>& p) const override;
  const char* name() const override { return TextDesc::name(); }

 private:
  // Equal slices of a span of one coordinate, each listing the items (glyphs, edges) that overlap it.
  struct Slices {
    double lo, size;
    std::vector<std::vector<uint32_t>> items;
    Slices(double from, double to, size_t count);
    size_t at(double v) const {  // the first slice for anything before the span, or NaN
      const double k = (v - lo) / size;
      return k > 0 ? size_t(std::min(k, double(items.size() - 1))) : 0;
    }
    void add(uint32_t item, double from, double to);
  };
  // Whether the glyph fills the point of its plane, by the non-zero rule.
  bool covers(size_t glyph, const glm::dvec2& p) const;
  // The glyph's faces and walls met strictly between `from` and `best`, which a hit lowers.
  void hitGlyph(size_t glyph, const glm::dvec3& o, const glm::dvec3& d, double from, double& best, glm::dvec3& point,
                glm::dvec3& normal) const;

  std::shared_ptr<const std::vector<PlacedGlyph>> glyphs_;
  double thickness_;
  Aabb<double> bounds_;
  Slices columns_;             // the glyphs, along x
  std::vector<Slices> bands_;  // each glyph's edges, along y
};

}  // namespace rt
