// Malformed scenes of our own: each one is refused with exactly one located message, asserted whole.
// The real executable is run on a few of them by tests/malformed/ (see tests/CMakeLists.txt).
#include <string>

#include <catch2/catch.hpp>

#include "raytrace/util/error.hpp"
#include "raytrace/parse/pov_parser.hpp"

using namespace std::string_literals;

namespace {

struct Malformed {
  const char* name;
  std::string text;  // std::string so that embedded NUL bytes stay in
  const char* message;
};

// Most cases start with a valid camera, so that each fails only where it means to.
const Malformed kCases[] = {
    {"binary_png",
     "\x89""PNG\r\n\x1A""\n\x00""\x00""\x00""\rIHDR"s,
     "m.pov:1:1: error: unexpected byte 0x89 (is this a text scene file?)"},
    {"camera_no_brace",
     "camera location <0,0,0>\n"s,
     "m.pov:1:8: error: expected '{' after 'camera', found 'location'"},
    {"camera_parallel",
     "camera { location <0,0,5> look_at <0,0,0> up <0,2,0> right <0,1,0> }\n"s,
     "m.pov:1:1: error: the camera's up and right vectors are parallel"},
    {"camera_same",
     "camera { location <1,2,3> look_at <1,2,3> }\n"s,
     "m.pov:1:1: error: the camera's look_at equals its location"},
    {"camera_unclosed",
     "camera {\n  location <0,0,5>\n"s,
     "m.pov:3:1: error: end of file inside the camera started at line 1; expected '}'"},
    {"camera_unknown",
     "camera { location <0,0,5> look_at <0,0,0> angle 60 }\n"s,
     "m.pov:1:43: error: unknown camera property 'angle'"},
    {"camera_zero_up",
     "camera { location <0,0,5> look_at <0,0,0> up <0,0,0> }\n"s,
     "m.pov:1:1: error: the camera's up vector is zero"},
    {"color_kw",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 pigment { color rgba <1,0,0,0> } }\n"s,
     "m.pov:2:37: error: expected 'rgb' or 'rgbf' in the pigment colour, found 'rgba'"},
    {"color_rgb5",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 pigment { color rgb <1,0,0,0,0> } }\n"s,
     "m.pov:2:51: error: an 'rgb' colour needs 3 or 4 components, found 5"},
    {"comment_open",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "/* a comment\nthat never ends\n"s,
     "m.pov:2:1: error: comment '/*' is never closed"},
    {"cone_same",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "cone { <0,1,0>, 1, <0,1,0>, 0.5 }\n"s,
     "m.pov:2:8: error: the cone's base and cap centres are the same point"},
    {"cone_zero",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "cone { <0,0,0>, 0, <0,1,0>, 0 }\n"s,
     "m.pov:2:8: error: both cone radii are zero"},
    {"control_byte",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 }\x01""\n"s,
     "m.pov:2:22: error: unexpected byte 0x01 (is this a text scene file?)"},
    {"crlf",
     "camera {\r\n  location <0,0,5>\r\n  look_at <0,0,0>\r\n}\r\nsphere { <0,0,0>, 1 }}\r\n"s,
     "m.pov:5:22: error: expected 'camera', 'light_source' or an object, found '}'"},
    {"cylinder_same",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "cylinder { <0,0,0>, <0,0,0>, 1 }\n"s,
     "m.pov:2:12: error: the cylinder's base and cap centres are the same point"},
    {"empty",
     ""s,
     "m.pov:1:1: error: the scene has no camera"},
    {"filter_range",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 pigment { color rgbf <1,0,0,1.5> } }\n"s,
     "m.pov:2:42: error: filter must be between 0 and 1, found 1.5"},
    {"finish_number",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 finish { ambient } }\n"s,
     "m.pov:2:38: error: expected a number after 'ambient', found '}'"},
    {"finish_unknown",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 finish { phong 1 } }\n"s,
     "m.pov:2:30: error: unknown finish property 'phong'"},
    {"inf_word",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, inf }\n"s,
     "m.pov:2:19: error: expected a number for the sphere radius, found 'inf'"},
    {"ior_neg",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 finish { ior -1.5 } }\n"s,
     "m.pov:2:34: error: ior must be greater than 0, found -1.5"},
    {"junk_top",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "42\n"s,
     "m.pov:2:1: error: expected 'camera', 'light_source' or an object, found '42'"},
    {"light_extra",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "light_source { <0,0,0> color rgb <1,1,1> shadowless }\n"s,
     "m.pov:2:42: error: unknown light_source property 'shadowless'"},
    {"light_nocolor",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "light_source { <0,0,0> }\n"s,
     "m.pov:2:24: error: expected 'rgb' or 'rgbf' in the light colour, found '}'"},
    {"light_unclosed",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "light_source { <0,0,0> color rgb <1,1,1>\n"s,
     "m.pov:3:1: error: end of file inside the light_source started at line 2; expected '}'"},
    {"nan_word",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <nan,0,0>, 1 }\n"s,
     "m.pov:2:11: error: expected a number in the sphere center, found 'nan'"},
    {"nocamera",
     "sphere { <0,0,0>, 1 }\n"s,
     "m.pov:2:1: error: the scene has no camera"},
    {"nul_byte",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "\x00""sphere { <0,0,0>, 1 }\n"s,
     "m.pov:2:1: error: unexpected byte 0x00 (is this a text scene file?)"},
    {"overflow",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1e999 }\n"s,
     "m.pov:2:19: error: number '1e999' is out of range"},
    {"overflow_neg",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <-1e400,0,0>, 1 }\n"s,
     "m.pov:2:11: error: number '-1e400' is out of range"},
    {"pigment_unclosed",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 pigment { color rgb <1,0,0> finish { } }\n"s,
     "m.pov:2:49: error: expected '}' to close the pigment, found 'finish'"},
    {"plane_zero",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "plane { <0,0,0>, 1 }\n"s,
     "m.pov:2:9: error: the plane normal is zero"},
    {"roughness0",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 finish { roughness 0 } }\n"s,
     "m.pov:2:40: error: roughness must be greater than 0, found 0"},
    {"scale_zero",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 scale <1,0,1> }\n"s,
     "m.pov:2:27: error: a scale factor is zero"},
    {"scale_zero_uniform",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1 scale 0 }\n"s,
     "m.pov:2:27: error: a scale factor is zero"},
    {"sphere_comma",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0> 1 }\n"s,
     "m.pov:2:18: error: expected ',' after the sphere center, found '1'"},
    {"sphere_radius0",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 0 }\n"s,
     "m.pov:2:19: error: the sphere radius must be greater than 0, found 0"},
    {"sphere_radius_neg",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, -2.5 }\n"s,
     "m.pov:2:19: error: the sphere radius must be greater than 0, found -2.5"},
    {"sphere_unclosed",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,0,0>, 1\n  pigment { color rgb <1,0,0> }\n"s,
     "m.pov:4:1: error: end of file inside the sphere started at line 2; expected '}'"},
    {"tab_cols",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "\tsphere\t{\t<0,0,0>,\t-1 }\n"s,
     "m.pov:2:20: error: the sphere radius must be greater than 0, found -1"},
    {"unknown_kw",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "spheer { <0,0,0>, 1 }\n"s,
     "m.pov:2:1: error: unknown keyword 'spheer'"},
    {"utf8",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sph\xC3""\xA8""re { <0,0,0>, 1 }\n"s,
     "m.pov:2:4: error: unexpected byte 0xC3 (is this a text scene file?)"},
    {"vec_long",
     "camera { location <0,0,1,2> look_at <0,0,0> }\n"s,
     "m.pov:1:27: error: the camera location needs 3 components, found 4"},
    {"vec_short",
     "camera { location <0,0> look_at <0,0,0> }\n"s,
     "m.pov:1:23: error: the camera location needs 3 components, found 2"},
    {"vec_unclosed",
     "camera { location <0,0,1 look_at <0,0,0> }\n"s,
     "m.pov:1:26: error: expected ',' or '>' in the camera location, found 'look_at'"},
    {"vec_word",
     "camera { location <0,0,5> look_at <0,0,0> }\n"
     "sphere { <0,x,0>, 1 }\n"s,
     "m.pov:2:13: error: expected a number in the sphere center, found 'x'"},
};

}  // namespace

TEST_CASE("every malformed scene gets its one located message", "[malformed]") {
  for (const Malformed& m : kCases) {
    CAPTURE(m.name);
    try {
      rt::parsePov(m.text, "m.pov");
      FAIL("parsed without an error");
    } catch (const rt::ParseError& e) {
      CHECK(std::string(e.what()) == m.message);
    }
  }
}
