// The text shape: glyphs of the fonts Debian's fonts-povray installs, extruded. The 'I' of cyrvetic.ttf is an
// exact rectangle in its font units (79..178 across, 0..728 up, 1000 to the em); first in a string it is moved
// left by its bearing, 79, so it fills x 0..0.099 and y 0..0.728, and its hits have exact answers.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/shapes/text.hpp"

using namespace rt;

namespace {

const std::string kFonts = "/usr/share/fonts/truetype/povray/";

TextDesc textOf(const std::string& font, const std::string& text, double thickness = 0.5,
                const glm::dvec3& offset = glm::dvec3(0)) {
  TextDesc d{std::make_shared<const TextDesc::Written>(TextDesc::Written{kFonts + font, text, offset}), thickness,
             nullptr};
  d.glyphs =
      std::make_shared<const std::vector<PlacedGlyph>>(textOutline(kFonts + font, text, glm::dvec2(offset), SourceLoc{}));
  return d;
}

std::optional<Hit<double>> shoot(const Text<double>& t, const glm::dvec3& origin, const glm::dvec3& dir) {
  return t.intersect(Ray<double>{origin, dir}, Interval<double>{});
}

SceneDesc povScene(const std::string& body) {
  return povray::parsePovRay("#version 3.7;\n" + body, "scene.pov", povray::PovRayOptions{{}, 320, 240, false});
}

std::string povFailure(const std::string& body) {
  try {
    povScene(body);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("text: the faces of an 'I' are met at the exact t, with normals -z in front and +z behind", "[text]") {
  const Text<double> text(textOf("cyrvetic.ttf", "I"), Material{}, 1);
  const auto front = shoot(text, {0.05, 0.3, -5}, {0, 0, 1});
  REQUIRE(front);
  CHECK(front->t == 5);
  CHECK(front->normal == glm::dvec3(0, 0, -1));
  CHECK(front->point == glm::dvec3(0.05, 0.3, 0));
  const auto back = shoot(text, {0.05, 0.3, 5}, {0, 0, -1});
  REQUIRE(back);
  CHECK(back->t == 4.5);
  CHECK(back->normal == glm::dvec3(0, 0, 1));
  // From inside, the face ahead, with its outward normal.
  const auto out = shoot(text, {0.05, 0.3, 0.25}, {0, 0, 1});
  REQUIRE(out);
  CHECK(out->t == 0.25);
  CHECK(out->normal == glm::dvec3(0, 0, 1));
  // Beside the stroke, nothing.
  CHECK_FALSE(shoot(text, {-0.001, 0.3, -5}, {0, 0, 1}));
  CHECK_FALSE(shoot(text, {0.1, 0.3, -5}, {0, 0, 1}));
  CHECK_FALSE(shoot(text, {0.05, 0.729, -5}, {0, 0, 1}));
}

TEST_CASE("text: the walls of an 'I' are its edges extruded, with the edges' outward normals", "[text]") {
  const Text<double> text(textOf("cyrvetic.ttf", "I"), Material{}, 1);
  const auto left = shoot(text, {-1, 0.3, 0.25}, {1, 0, 0});
  REQUIRE(left);
  CHECK(left->t == Approx(1).epsilon(1e-12));
  CHECK(left->normal == glm::dvec3(-1, 0, 0));
  const auto right = shoot(text, {5, 0.3, 0.25}, {-1, 0, 0});
  REQUIRE(right);
  CHECK(right->t == Approx(5 - 0.099).epsilon(1e-12));
  CHECK(right->normal == glm::dvec3(1, 0, 0));
  const auto top = shoot(text, {0.05, 5, 0.4}, {0, -1, 0});
  REQUIRE(top);
  CHECK(top->t == Approx(5 - 0.728).epsilon(1e-12));
  CHECK(top->normal == glm::dvec3(0, 1, 0));
  const auto bottom = shoot(text, {0.05, -5, 0.1}, {0, 1, 0});
  REQUIRE(bottom);
  CHECK(bottom->t == Approx(5).epsilon(1e-12));
  CHECK(bottom->normal == glm::dvec3(0, -1, 0));
  const auto bounds = text.bounds();
  REQUIRE(bounds);
  CHECK(bounds->min == glm::dvec3(0));
  CHECK(bounds->max.x == Approx(0.099));
  CHECK(bounds->max.y == Approx(0.728));
  CHECK(bounds->max.z == 0.5);
}

TEST_CASE("text: a ray through the middle of an 'O' passes through its hole, one through the stroke does not",
          "[text]") {
  const TextDesc desc = textOf("timrom.ttf", "O");
  REQUIRE(desc.glyphs->size() == 1);
  const PlacedGlyph& o = desc.glyphs->front();
  const Text<double> text(desc, Material{}, 1);
  const glm::dvec2 middle = (o.lo + o.hi) / 2.0;
  CHECK_FALSE(shoot(text, glm::dvec3(middle, -5), {0, 0, 1}));
  CHECK_FALSE(text.inside(glm::dvec3(middle, 0.25)));
  // Just inside the left extreme of the bowl: the stroke.
  const glm::dvec3 stroke(o.lo.x + 0.02, middle.y, 0.25);
  CHECK(text.inside(stroke));
  const auto hit = shoot(text, {stroke.x, stroke.y, -5}, {0, 0, 1});
  REQUIRE(hit);
  CHECK(hit->t == 5);
  // Along the middle line from the left: the outer wall, facing left, at the bowl's extreme.
  const auto wall = shoot(text, {-1, middle.y, 0.25}, {1, 0, 0});
  REQUIRE(wall);
  CHECK(wall->point.x == Approx(o.lo.x).margin(1e-3));
  CHECK(wall->normal.x == Approx(-1).margin(1e-3));
}

TEST_CASE("text: inside() agrees with the parity of the walls and faces crossed by seeded random rays", "[text]") {
  const Text<double> text(textOf("timrom.ttf", "Og&", 0.3, {0.05, 0.02, 0.1}), Material{}, 1);
  const auto bounds = text.bounds();
  REQUIRE(bounds);
  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> unit(0, 1), signed1(-1, 1);
  int insideCount = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 p = bounds->min + glm::dvec3(unit(rng), unit(rng), unit(rng)) * (bounds->max - bounds->min);
    const glm::dvec3 dir = glm::normalize(glm::dvec3(signed1(rng), signed1(rng), signed1(rng)));
    int crossings = 0;
    double from = 0;
    while (const auto hit = text.intersect(Ray<double>{p, dir}, Interval<double>{from + 1e-9})) {
      ++crossings;
      from = hit->t;
    }
    CAPTURE(i, p.x, p.y, p.z, dir.x, dir.y, dir.z);
    CHECK(text.inside(p) == (crossings % 2 == 1));
    insideCount += text.inside(p);
  }
  CHECK(insideCount > 100);  // the test saw both sides
}

TEST_CASE("text: glyphs follow one another by their advance, the font's kerning and the offset", "[text]") {
  // cyrvetic's 'I' advances 263 units from its bearing of 79; the next one stands that far on, plus the offset.
  const TextDesc two = textOf("cyrvetic.ttf", "II", 0.5, {0.1, 0.2, 0.3});
  REQUIRE(two.glyphs->size() == 2);
  const PlacedGlyph& second = (*two.glyphs)[1];
  CHECK(second.lo.x == Approx(0.263 + 0.1));
  CHECK(second.lo.y == Approx(0.2));
  CHECK(two.bounds().max.z == 0.5);  // the offset's z is left out, as POV-Ray does
  // timrom's 'A' advances 750 units from its bearing of 6, "AV" kerns by -187, and the 'V' has no bearing.
  const TextDesc av = textOf("timrom.ttf", "AV");
  REQUIRE(av.glyphs->size() == 2);
  CHECK((*av.glyphs)[0].lo.x == 0);
  CHECK((*av.glyphs)[1].lo.x == Approx(0.750 - 0.006 - 0.187));
}

TEST_CASE("text: an empty string draws nothing, a blank only advances, an unknown character is the missing glyph",
          "[text]") {
  const TextDesc empty = textOf("timrom.ttf", "");
  CHECK(empty.glyphs->empty());
  const Text<double> nothing(empty, Material{}, 1);
  CHECK_FALSE(shoot(nothing, {0, 0, -5}, {0, 0, 1}));
  CHECK_FALSE(nothing.inside({0, 0, 0.25}));
  CHECK(empty.boundingBall().radius == 0);

  const TextDesc blank = textOf("cyrvetic.ttf", "I I");
  REQUIRE(blank.glyphs->size() == 2);
  CHECK((*blank.glyphs)[1].lo.x == Approx(0.263 + 0.277));
  // A character cyrvetic lacks (U+4E2D, in UTF-8) is its missing glyph, a box advancing 612 units.
  const TextDesc unknown = textOf("cyrvetic.ttf", "I\xe4\xb8\xadI");
  REQUIRE(unknown.glyphs->size() == 3);
  CHECK((*unknown.glyphs)[2].lo.x == Approx(0.263 + 0.612));
}

TEST_CASE("text: POV-Ray's text statement, with internal fonts by number and fonts found where POV-Ray looks",
          "[text]") {
  const SceneDesc s = povScene(R"(
text { ttf "timrom.ttf" "Hi" 0.25, <0.1, 0, 0> }
text { internal 1 "Hi" 0.25, 0 }
text { internal 7 "P" 1, 0 }
text { ttf "cyrvetic", "Hi", 0.25, 0 }
)");
  REQUIRE(s.objects.size() == 4);
  const auto& ttf = std::get<TextDesc>(s.objects[0].shape);
  CHECK(ttf.written->text == "Hi");
  CHECK(ttf.thickness == 0.25);
  CHECK(ttf.written->offset == glm::dvec3(0.1, 0, 0));
  CHECK(ttf.glyphs->size() == 2);
  CHECK(std::get<TextDesc>(s.objects[1].shape).written->font.find("timrom.ttf") != std::string::npos);
  CHECK(std::get<TextDesc>(s.objects[2].shape).written->font.find("povlogo.ttf") != std::string::npos);
  CHECK(std::get<TextDesc>(s.objects[2].shape).glyphs->size() == 1);  // the logo is its 'P'
  CHECK(std::get<TextDesc>(s.objects[3].shape).written->font.find("cyrvetic.ttf") != std::string::npos);
}

TEST_CASE("text: strings are ASCII, bytes past 127 blanks, unless global_settings chooses charset utf8", "[text]") {
  const std::string text = "text { ttf \"cyrvetic.ttf\" \"I\xc3\xa4I\" 1, 0 }\n";
  CHECK(std::get<TextDesc>(povScene(text).objects[0].shape).glyphs->size() == 2);
  CHECK(std::get<TextDesc>(povScene("global_settings { charset utf8 }\n" + text).objects[0].shape).glyphs->size() == 3);
}

TEST_CASE("text: a font found nowhere is one message at its place, naming the font", "[text]") {
  CHECK(povFailure("sphere { 0, 1 }\ntext { ttf \"nofont.ttf\" \"Hi\" 1, 0 }") ==
        "scene.pov:3:12: error: cannot find the font file 'nofont.ttf'");
  CHECK(povFailure("text { \"timrom.ttf\" \"Hi\" 1, 0 }") ==
        "scene.pov:2:8: error: 'text' needs ttf and a font file name, or internal and a font number");
  CHECK(povFailure("text { ttf \"timrom.ttf\" 1, 0 }") ==
        "scene.pov:2:25: error: expected a string for the text, found a float");
}

TEST_CASE("text: the course language, which has no strings, refuses a text at its place", "[text]") {
  std::string message = "no error";
  try {
    parsePov("sphere { <0, 0, 0>, 1 }\ntext { ttf \"timrom.ttf\" \"Hi\" 1, 0 }\n", "course.pov");
  } catch (const Error& e) {
    message = e.what();
  }
  CHECK(message == "course.pov:2:8: error: 'text' is read only in POV-Ray 3.7 scenes");
}
