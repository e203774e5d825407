// The POV-subset parser (docs/reference/csc473.md §b): every construct, the defaults, and every error message whole,
// with its file:line:col.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "raytrace/parse/pov_parser.hpp"

using rt::parsePov;
using rt::SceneDesc;

namespace {

// Every scene needs a camera; this one is line 1, so the text under test starts on line 2.
const std::string kCamera = "camera { location <0,0,5> look_at <0,0,0> }\n";

SceneDesc parse(const std::string& body) { return parsePov(kCamera + body, "s.pov"); }

// The error message a scene body produces, or "" if it parses.
std::string errorOf(const std::string& body) {
  try {
    parse(body);
  } catch (const rt::ParseError& e) {
    return e.what();
  }
  return "";
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

}  // namespace

TEST_CASE("pov: the course's simple.pov-like scene, every field") {
  const SceneDesc s = parsePov(
      "// a comment\n"
      "camera {\n  location  <0, 0, 14>\n  up <0, 1, 0>\n  right <1.33333, 0, 0>\n  look_at <0, 0, 0>\n}\n"
      "light_source {<-100, 100, 100> color rgb <1.5, 1.5, 1.5>}\n"
      "sphere { <0, 0, 0>, 2\n  pigment { color rgb <1.0, 0.0, 1.0>}\n  finish {ambient 0.2 diffuse 0.4}\n"
      "  translate <0, 0, 0>\n}\n"
      "plane {<0, 1, 0>, -4\n pigment {color rgb <0.2, 0.2, 0.8>}\n finish {ambient 0.4 diffuse 0.8}\n}\n",
      "simple.pov");
  CHECK(s.file == "simple.pov");
  CHECK(s.camera.location == glm::dvec3(0, 0, 14));
  CHECK(s.camera.up == glm::dvec3(0, 1, 0));
  CHECK(s.camera.right == glm::dvec3(1.33333, 0, 0));
  CHECK(s.camera.lookAt == glm::dvec3(0, 0, 0));
  CHECK(s.camera.pixelOffset == glm::dvec2(0.5, 0.5));
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].position == glm::dvec3(-100, 100, 100));
  CHECK(s.lights[0].color == rt::Color(1.5f));
  REQUIRE(s.objects.size() == 2);
  const auto& sphere = std::get<rt::SphereDesc>(s.objects[0].shape);
  CHECK(sphere.center == glm::dvec3(0));
  CHECK(sphere.radius == 2.0);
  CHECK(s.objects[0].loc.str() == "simple.pov:9:1");
  CHECK(s.objects[0].material.pigment == rt::Color(1, 0, 1));
  CHECK(s.objects[0].finish->ambient == 0.2);
  CHECK(s.objects[0].finish->diffuse == 0.4);
  CHECK(s.objects[0].worldFromObject() == glm::dmat4(1.0));
  const auto& plane = std::get<rt::PlaneDesc>(s.objects[1].shape);
  CHECK(plane.normal == glm::dvec3(0, 1, 0));
  CHECK(plane.distance == -4.0);
  CHECK(s.objects[1].loc.str() == "simple.pov:14:1");
  CHECK(s.warnings.empty());
}

TEST_CASE("pov: defaults of §b") {
  const SceneDesc s = parsePov("camera {}\nsphere { <0,0,0>, 1 }", "d.pov");
  CHECK(s.camera.location == glm::dvec3(0, 0, 0));
  CHECK(s.camera.up == glm::dvec3(0, 1, 0));
  CHECK(s.camera.right == glm::dvec3(1.33333, 0, 0));
  CHECK(s.camera.lookAt == glm::dvec3(0, 0, -1));
  CHECK(s.lights.empty());
  const rt::Material& m = s.objects.at(0).material;
  const rt::Finish& f = *s.objects.at(0).finish;
  CHECK(m.pigment == rt::Color(0));
  CHECK(m.filter == 0.0f);
  CHECK(f.ambient == 0.0);
  CHECK(f.diffuse == 0.0);
  CHECK(f.specular == 0.0);
  CHECK(f.roughness == 1.0);
  CHECK(f.reflection == 0.0);
  CHECK(f.refraction == 0.0);
  CHECK(f.ior == 1.0);
  CHECK(m.exponent == 0.0f);  // 2/1² − 2
  CHECK(m.roughness == 1.0f);
  CHECK(m.reflection == 0.0f);
  CHECK(m.ior == 1.0f);
  CHECK(s.dialect.toByte() == rt::Dialect::ToByte::Round);
  CHECK(s.background == rt::Color(0));
}

TEST_CASE("pov: every shape with its parameters") {
  const SceneDesc s = parse(
      "sphere { <1,2,3>, 0.5 }\n"
      "plane { <0,0,2>, 3 }\n"
      "triangle { <0,0,0>, <1,0,0>, <0,1,0> }\n"
      "box { <-1,-2,-3>, <1,2,3> }\n"
      "cone { <0,0,0>, 1, <0,2,0>, 0 }\n"
      "cylinder { <0,0,0>, <0,0,4>, 0.25 }\n");
  REQUIRE(s.objects.size() == 6);
  CHECK(std::get<rt::SphereDesc>(s.objects[0].shape).center == glm::dvec3(1, 2, 3));
  CHECK(std::get<rt::SphereDesc>(s.objects[0].shape).radius == 0.5);
  // The normal is kept as written; normalization is the plane's business.
  CHECK(std::get<rt::PlaneDesc>(s.objects[1].shape).normal == glm::dvec3(0, 0, 2));
  CHECK(std::get<rt::PlaneDesc>(s.objects[1].shape).distance == 3.0);
  const auto& tri = std::get<rt::TriangleDesc>(s.objects[2].shape);
  CHECK((tri.a == glm::dvec3(0) && tri.b == glm::dvec3(1, 0, 0) && tri.c == glm::dvec3(0, 1, 0)));
  const auto& box = std::get<rt::BoxDesc>(s.objects[3].shape);
  CHECK((box.min == glm::dvec3(-1, -2, -3) && box.max == glm::dvec3(1, 2, 3)));
  const auto& cone = std::get<rt::ConeDesc>(s.objects[4].shape);
  CHECK((cone.base == glm::dvec3(0) && cone.baseRadius == 1 && cone.cap == glm::dvec3(0, 2, 0) && cone.capRadius == 0));
  const auto& cyl = std::get<rt::CylinderDesc>(s.objects[5].shape);
  CHECK((cyl.base == glm::dvec3(0) && cyl.cap == glm::dvec3(0, 0, 4) && cyl.radius == 0.25));
  for (size_t i = 0; i < s.objects.size(); ++i) CHECK(s.objects[i].loc.line == int(i) + 2);
  CHECK(std::string(rt::shapeName(s.objects[5].shape)) == "Cylinder");
}

TEST_CASE("pov: colours: rgb, rgbf with 3 or 4 values, with or without 'color'/'colour'") {
  const SceneDesc s = parse(
      "sphere { <0,0,0>, 1 pigment { color rgb <0.1, 0.2, 0.3> } }\n"
      "sphere { <0,0,0>, 1 pigment { color rgbf <0.1, 0.2, 0.3, 0.75> } }\n"
      "sphere { <0,0,0>, 1 pigment { color rgbf <0.4, 0.5, 0.6> } }\n"
      "sphere { <0,0,0>, 1 pigment { rgb <1, 1, 1> } }\n"
      "sphere { <0,0,0>, 1 pigment { colour rgbf <0, 0, 0, 1> } }\n"
      "light_source { <0,0,0> rgb <2, 3, 4> }\n");
  CHECK(s.objects[0].material.pigment == rt::Color(0.1f, 0.2f, 0.3f));
  CHECK(s.objects[0].material.filter == 0.0f);
  CHECK(s.objects[1].material.pigment == rt::Color(0.1f, 0.2f, 0.3f));
  CHECK(s.objects[1].material.filter == 0.75f);
  CHECK(s.objects[2].material.pigment == rt::Color(0.4f, 0.5f, 0.6f));
  CHECK(s.objects[2].material.filter == 0.0f);
  CHECK(s.objects[3].material.pigment == rt::Color(1));
  CHECK(s.objects[4].material.filter == 1.0f);
  CHECK(s.lights[0].color == rt::Color(2, 3, 4));
  CHECK(s.warnings.empty());
}

TEST_CASE("pov: 'rgb' with 4 values reads the fourth as the filter, with a warning, as POV-Ray 3.7 does") {
  const SceneDesc s = parse("sphere { <0,0,0>, 1\n  pigment { color rgb <.9, .9, .97, .9> } }");
  CHECK(s.objects[0].material.pigment == rt::Color(0.9f, 0.9f, 0.97f));
  CHECK(s.objects[0].material.filter == 0.9f);
  CHECK(s.warnings == std::vector<std::string>{"s.pov:3:23: warning: 'rgb' with 4 values; the fourth is read as the filter"});
}

TEST_CASE("pov: finish keys in any order; a later finish block changes only what it names") {
  const SceneDesc s = parse(
      "sphere { <0,0,0>, 1 finish { ior 1.5 refraction 1 reflection 0.25 roughness 0.5 specular 0.7 diffuse 0.6 "
      "ambient 0.1 } pigment { rgb <1, 0.5, 0.25> } finish { ambient 0.3 } }");
  const rt::Material& m = s.objects[0].material;
  const rt::Finish& f = *s.objects[0].finish;
  CHECK(f.ambient == 0.3);
  CHECK(f.diffuse == 0.6);
  CHECK(f.specular == 0.7);
  CHECK(f.roughness == 0.5);
  CHECK(f.reflection == 0.25);
  CHECK(f.refraction == 1.0);
  CHECK(f.ior == 1.5);
  // The per-term colours are the finish weights times the pigment (§c), whatever the order written.
  CHECK(m.ambient == rt::Color(0.3f) * rt::Color(1, 0.5f, 0.25f));
  CHECK(m.diffuse == rt::Color(0.6f) * rt::Color(1, 0.5f, 0.25f));
  CHECK(m.specular == rt::Color(0.7f) * rt::Color(1, 0.5f, 0.25f));
  CHECK(m.exponent == 6.0f);  // 2/0.5² − 2 (§c.1)
  CHECK(m.roughness == 0.5f);
  CHECK(m.reflection == 0.25f);
  CHECK(m.ior == 1.5f);
}

TEST_CASE("pov: the 'metallic' finish key is read and ignored with a located warning") {
  const SceneDesc s = parse("sphere { <0,0,0>, 1 finish { ambient 0.2\n metallic 0.5 diffuse 0.3 } }");
  CHECK(s.objects[0].finish->diffuse == 0.3);
  CHECK(s.warnings == std::vector<std::string>{"s.pov:3:2: warning: 'metallic' is not modelled and is ignored"});
}

TEST_CASE("pov: transforms compose in file order, repeated, before and after pigment and finish") {
  const SceneDesc s = parse(
      "sphere { <0,0,0>, 1 scale 2 translate <1,0,0> }\n"
      "sphere { <0,0,0>, 1 translate <1,0,0> scale 2 }\n"
      "sphere { <0,0,0>, 1 rotate <0,0,90> pigment { rgb <1,0,0> } translate <0,0,1> finish { ambient 1 }"
      " scale <1,2,3> }\n"
      "sphere { <0,0,0>, 1 rotate <90,90,0> }\n"
      "plane { <0,1,0>, 0 translate <0,-1,0> rotate <0,0,180> }\n");
  CHECK(apply(s.objects[0].worldFromObject(), {1, 0, 0}) == glm::dvec3(3, 0, 0));  // scale, then translate
  CHECK(apply(s.objects[1].worldFromObject(), {1, 0, 0}) == glm::dvec3(4, 0, 0));  // translate, then scale
  // rotate z 90: x → y; translate z; then scale <1,2,3>.
  const glm::dvec3 p = apply(s.objects[2].worldFromObject(), {1, 0, 0});
  CHECK(p.x == Approx(0).margin(1e-12));
  CHECK(p.y == Approx(2));
  CHECK(p.z == Approx(3));
  CHECK(s.objects[2].material.pigment == rt::Color(1, 0, 0));
  CHECK(s.objects[2].finish->ambient == 1.0);
  // The course's R = Rx·Ry·Rz turns about z, then y, then x (§c.10): x →(y 90)→ −z →(x 90)→ y.
  const glm::dvec3 q = apply(s.objects[3].worldFromObject(), {1, 0, 0});
  CHECK(q.x == Approx(0).margin(1e-12));
  CHECK(q.y == Approx(1));
  CHECK(q.z == Approx(0).margin(1e-12));
  // Transforms apply to planes too.
  const glm::dvec3 r = apply(s.objects[4].worldFromObject(), {0, 0, 0});
  CHECK(r.x == Approx(0).margin(1e-12));
  CHECK(r.y == Approx(1));
}

TEST_CASE("pov: whitespace and comments anywhere, CRLF and CR-only files") {
  const std::string text =
      "camera{location<0,0,5>look_at<0,0,0>}sphere{<0,0,0>,1 pigment{rgb<1,1,1>}}";
  CHECK(parsePov(text, "a.pov").objects.size() == 1);
  const std::string spread =
      "camera\n{\nlocation\n<\n0\n,\n0\n,\n5\n>\n}\n/* block */ sphere // line\n{ <0,0,0>\n,\n1\n}\n";
  CHECK(parsePov(spread, "b.pov").objects.at(0).loc.str() == "b.pov:12:13");
  std::string crlf, cr;
  for (char c : spread) {
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    cr += c == '\n' ? '\r' : c;
  }
  CHECK(parsePov(crlf, "c.pov").objects.at(0).loc.str() == "c.pov:12:13");
  CHECK(parsePov(cr, "d.pov").objects.at(0).loc.str() == "d.pov:12:13");
}

TEST_CASE("pov: the number forms of the course files") {
  const SceneDesc s = parse("sphere { <.94, -.001, 1.>, 1e-05 scale +2 }\nplane { <0,1,0>, -0 }");
  CHECK(std::get<rt::SphereDesc>(s.objects[0].shape).center == glm::dvec3(0.94, -0.001, 1.0));
  CHECK(std::get<rt::SphereDesc>(s.objects[0].shape).radius == 1e-05);
  CHECK(apply(s.objects[0].worldFromObject(), {1, 1, 1}) == glm::dvec3(2, 2, 2));
  CHECK(std::signbit(std::get<rt::PlaneDesc>(s.objects[1].shape).distance));
}

TEST_CASE("pov: unknown keywords and stray tokens") {
  CHECK(errorOf("box2 { }") == "s.pov:2:1: error: unknown keyword 'box2'");
  CHECK(errorOf("  }") == "s.pov:2:3: error: expected 'camera', 'light_source' or an object, found '}'");
  CHECK(errorOf("5") == "s.pov:2:1: error: expected 'camera', 'light_source' or an object, found '5'");
  CHECK(errorOf("\n/light_source { <0,0,0> rgb <1,1,1> }") ==
        "s.pov:3:1: error: expected 'camera', 'light_source' or an object, found '/'");
  CHECK_THROWS_WITH(parsePov("camera { location <0,0,5> look-at <0,0,0> }", "s.pov"),
                    "s.pov:1:27: error: unknown camera property 'look'");
  CHECK(errorOf("sphere { <0,0,0>, 1 color rgb <1,0,0> }") == "s.pov:2:21: error: unknown sphere property 'color'");
  CHECK(errorOf("sphere { <0,0,0>, 1 finish { shiny 1 } }") == "s.pov:2:30: error: unknown finish property 'shiny'");
  // Commas between finish items: POV-Ray 3.7 rejects them too ("No matching } in 'finish', , found instead").
  CHECK(errorOf("sphere { <0,0,0>, 1 finish { ambient 0.5, diffuse 1 } }") ==
        "s.pov:2:41: error: unknown finish property ','");
  CHECK(errorOf("light_source { <0,0,0> rgb <1,1,1> fade 1 }") ==
        "s.pov:2:36: error: unknown light_source property 'fade'");
  CHECK(errorOf("sphere { <0,0,0>, 1 pigment { red 1 } }") ==
        "s.pov:2:31: error: expected 'rgb' or 'rgbf' in the pigment colour, found 'red'");
  CHECK(errorOf("light_source { <0,0,0> 1 }") ==
        "s.pov:2:24: error: expected 'rgb' or 'rgbf' in the light colour, found '1'");
}

TEST_CASE("pov: missing braces") {
  CHECK_THROWS_WITH(parsePov("camera location <0,0,5>", "s.pov"),
                    "s.pov:1:8: error: expected '{' after 'camera', found 'location'");
  CHECK(errorOf("sphere <0,0,0>, 1 }") == "s.pov:2:8: error: expected '{' after 'sphere', found '<'");
  CHECK(errorOf("light_source <0,0,0> rgb <1,1,1> }") ==
        "s.pov:2:14: error: expected '{' after 'light_source', found '<'");
  CHECK(errorOf("sphere { <0,0,0>, 1 pigment rgb <1,0,0> }") ==
        "s.pov:2:29: error: expected '{' after 'pigment', found 'rgb'");
  CHECK(errorOf("sphere { <0,0,0>, 1 finish ambient 1 }") ==
        "s.pov:2:28: error: expected '{' after 'finish', found 'ambient'");
  CHECK(errorOf("sphere { <0,0,0>, 1 pigment { rgb <1,0,0> finish { } }") ==
        "s.pov:2:43: error: expected '}' to close the pigment, found 'finish'");
}

TEST_CASE("pov: bad vectors") {
  CHECK(errorOf("sphere { <0 0 0>, 1 }") == "s.pov:2:13: error: expected ',' or '>' in the sphere center, found '0'");
  CHECK(errorOf("sphere { <0,0>, 1 }") == "s.pov:2:14: error: the sphere center needs 3 components, found 2");
  CHECK(errorOf("sphere { <0,0,0,0>, 1 }") == "s.pov:2:18: error: the sphere center needs 3 components, found 4");
  CHECK(errorOf("sphere { <0,x,0>, 1 }") == "s.pov:2:13: error: expected a number in the sphere center, found 'x'");
  CHECK(errorOf("sphere { 0, 1 }") == "s.pov:2:10: error: expected '<' to start the sphere center, found '0'");
  CHECK(errorOf("sphere { <0,0,0> 1 }") == "s.pov:2:18: error: expected ',' after the sphere center, found '1'");
  CHECK(errorOf("sphere { <0,0,0>, }") == "s.pov:2:19: error: expected a number for the sphere radius, found '}'");
  CHECK(errorOf("plane { <0,1,0>, }") == "s.pov:2:18: error: expected a number for the plane distance, found '}'");
  CHECK(errorOf("sphere { <0,0,0>, 1 pigment { rgb <1,0> } }") ==
        "s.pov:2:39: error: an 'rgb' colour needs 3 or 4 components, found 2");
  CHECK(errorOf("sphere { <0,0,0>, 1 pigment { rgbf <1,0,0,0,0> } }") ==
        "s.pov:2:46: error: an 'rgbf' colour needs 3 or 4 components, found 5");
  CHECK_THROWS_WITH(parsePov("camera { up <0,1> }", "s.pov"),
                    "s.pov:1:17: error: the camera up vector needs 3 components, found 2");
  CHECK(errorOf("sphere { <0,0,0>, 1 scale <1,2> }") == "s.pov:2:31: error: the scale needs 3 components, found 2");
  CHECK(errorOf("sphere { <0,0,0>, 1 scale x }") == "s.pov:2:27: error: expected '<' to start the scale, found 'x'");
  CHECK(errorOf("sphere { <0,0,0>, 1 rotate 90 }") ==
        "s.pov:2:28: error: expected '<' to start the rotation, found '90'");
  CHECK(errorOf("sphere { <0,0,0>, 1e999 }") == "s.pov:2:19: error: number '1e999' is out of range");
}

TEST_CASE("pov: end of file inside a block") {
  CHECK_THROWS_WITH(parsePov("camera { location <0,0,5>", "s.pov"),
                    "s.pov:1:26: error: end of file inside the camera started at line 1; expected '}'");
  CHECK(errorOf("sphere { <0,0,0>, 1\n pigment { rgb <1,1,1> }\n") ==
        "s.pov:4:1: error: end of file inside the sphere started at line 2; expected '}'");
  CHECK(errorOf("\nlight_source { <0,0,0> rgb <1,1,1>") ==
        "s.pov:3:35: error: end of file inside the light_source started at line 3; expected '}'");
  CHECK(errorOf("sphere { <0,0,0>, 1 finish { ambient 1") ==
        "s.pov:2:39: error: end of file inside the finish started at line 2; expected '}'");
  CHECK(errorOf("sphere { <0,0,0>, 1 pigment { rgb <1,1,1>") ==
        "s.pov:2:42: error: expected '}' to close the pigment, found end of file");
  CHECK(errorOf("sphere { <0,0,0>, 1 finish { ambient") ==
        "s.pov:2:37: error: expected a number after 'ambient', found end of file");
  CHECK(errorOf("sphere { <0,0") == "s.pov:2:14: error: expected ',' or '>' in the sphere center, found end of file");
  CHECK(errorOf("sphere") == "s.pov:2:7: error: expected '{' after 'sphere', found end of file");
}

TEST_CASE("pov: impossible shapes") {
  CHECK(errorOf("sphere { <0,0,0>, 0 }") == "s.pov:2:19: error: the sphere radius must be greater than 0, found 0");
  CHECK(errorOf("sphere { <0,0,0>, -1.5 }") ==
        "s.pov:2:19: error: the sphere radius must be greater than 0, found -1.5");
  CHECK(errorOf("plane { <0,0,0>, 1 }") == "s.pov:2:9: error: the plane normal is zero");
  CHECK(errorOf("cylinder { <0,0,0>, <0,1,0>, 0 }") ==
        "s.pov:2:30: error: the cylinder radius must be greater than 0, found 0");
  CHECK(errorOf("cylinder { <1,1,1>, <1,1,1>, 1 }") ==
        "s.pov:2:12: error: the cylinder's base and cap centres are the same point");
  CHECK(errorOf("cone { <0,0,0>, -1, <0,1,0>, 0 }") ==
        "s.pov:2:17: error: the cone base radius must not be negative, found -1");
  CHECK(errorOf("cone { <0,0,0>, 0, <0,1,0>, 0 }") == "s.pov:2:8: error: both cone radii are zero");
  CHECK(errorOf("cone { <0,0,0>, 1, <0,0,0>, 0 }") ==
        "s.pov:2:8: error: the cone's base and cap centres are the same point");
  CHECK(errorOf("torus { 1, 0 }") == "s.pov:2:12: error: the torus minor radius must be greater than 0, found 0");
  CHECK(errorOf("poly { 8, <1, 2> }") == "s.pov:2:8: error: the poly order must be from 2 to 7, found 8");
  CHECK(errorOf("quadric { <0,0,0>, <0,0,0>, <0,0,0>, 1 }") ==
        "s.pov:2:11: error: the quadric's coefficients of x, y and z are all zero");
  CHECK(errorOf("cubic { <0,0,0,0, 0,0,0, 0,0,0, 0,0,0, 0,0,0, 0,0,0, 5> }") ==
        "s.pov:2:9: error: the cubic coefficients of x, y and z are all zero");
  CHECK(errorOf("cubic { <1, 2, 3> }") == "s.pov:2:17: error: the cubic coefficients need 20 numbers, found 3");
}

TEST_CASE("pov: the polynomial shapes, coefficients in POV-Ray's order") {
  const SceneDesc s = parse("torus { 2, 0.5 }\nquadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 }\n"
                            "poly { 2, <1,0,0,0, 1,0,0, 1,0, -1> }\n"
                            "quartic { <1,0,0,0,2,0,0,2,0, -104,0,0,0,0,0,0,0,0, 0,0,1,0,0,2,0,56,0, 0,0,0,1,0,-104,0,784> }");
  REQUIRE(s.objects.size() == 4);
  CHECK(std::get<rt::TorusDesc>(s.objects[0].shape).major == 2);
  CHECK(std::get<rt::QuadricDesc>(s.objects[1].shape).constant == -1);
  CHECK(std::get<rt::PolyDesc>(s.objects[2].shape).order == 2);
  const auto& quartic = std::get<rt::PolyDesc>(s.objects[3].shape);
  CHECK(quartic.order == 4);
  REQUIRE(quartic.coefficients.size() == 35);
  CHECK(quartic.coefficients[34] == 784);
}

TEST_CASE("pov: impossible cameras, located at the camera keyword") {
  CHECK_THROWS_WITH(parsePov("sphere { <0,0,0>, 1 }\n  camera { location <1,2,3> look_at <1,2,3> }", "s.pov"),
                    "s.pov:2:3: error: the camera's look_at equals its location");
  CHECK_THROWS_WITH(parsePov("camera { location <0,0,5> look_at <0,0,0> up <0,0,0> }", "s.pov"),
                    "s.pov:1:1: error: the camera's up vector is zero");
  CHECK_THROWS_WITH(parsePov("camera { location <0,0,5> look_at <0,0,0> right <0,0,0> }", "s.pov"),
                    "s.pov:1:1: error: the camera's right vector is zero");
  CHECK_THROWS_WITH(parsePov("camera { location <0,0,5> look_at <0,0,0> up <0,2,0> right <0,-1,0> }", "s.pov"),
                    "s.pov:1:1: error: the camera's up and right vectors are parallel");
}

TEST_CASE("pov: impossible materials and transforms") {
  CHECK(errorOf("sphere { <0,0,0>, 1 finish { roughness 0 } }") ==
        "s.pov:2:40: error: roughness must be greater than 0, found 0");
  CHECK(errorOf("sphere { <0,0,0>, 1 finish { ior -1.5 } }") ==
        "s.pov:2:34: error: ior must be greater than 0, found -1.5");
  CHECK(errorOf("sphere { <0,0,0>, 1 finish { ior 0 } }") == "s.pov:2:34: error: ior must be greater than 0, found 0");
  CHECK(errorOf("sphere { <0,0,0>, 1 scale <1,0,1> }") == "s.pov:2:27: error: a scale factor is zero");
  CHECK(errorOf("sphere { <0,0,0>, 1 scale 0 }") == "s.pov:2:27: error: a scale factor is zero");
  CHECK(errorOf("sphere { <0,0,0>, 1 pigment { rgbf <1,1,1,1.5> } }") ==
        "s.pov:2:36: error: filter must be between 0 and 1, found 1.5");
  CHECK(errorOf("sphere { <0,0,0>, 1 pigment { rgbf <1,1,1,-0.25> } }") ==
        "s.pov:2:36: error: filter must be between 0 and 1, found -0.25");
  CHECK(errorOf("sphere { <0,0,0>, 1 finish { ambient x } }") ==
        "s.pov:2:38: error: expected a number after 'ambient', found 'x'");
}

TEST_CASE("pov: a scene without a camera") {
  CHECK_THROWS_WITH(parsePov("sphere { <0,0,0>, 1 }\n", "s.pov"), "s.pov:2:1: error: the scene has no camera");
  CHECK_THROWS_WITH(parsePov("", "e.pov"), "e.pov:1:1: error: the scene has no camera");
}

TEST_CASE("pov: errors are ParseErrors carrying their location") {
  try {
    parse("sphere { <0,0,0>, 0 }");
    FAIL("no error");
  } catch (const rt::ParseError& e) {
    CHECK(e.loc().str() == "s.pov:2:19");
  }
}

TEST_CASE("pov: commas between shape parameters") {
  CHECK(errorOf("plane { <0,1,0> 1 }") == "s.pov:2:17: error: expected ',' after the plane normal, found '1'");
  CHECK(errorOf("triangle { <0,0,0> <1,0,0>, <0,1,0> }") ==
        "s.pov:2:20: error: expected ',' after the first triangle vertex, found '<'");
  CHECK(errorOf("triangle { <0,0,0>, <1,0,0> <0,1,0> }") ==
        "s.pov:2:29: error: expected ',' after the second triangle vertex, found '<'");
  CHECK(errorOf("box { <0,0,0> <1,1,1> }") == "s.pov:2:15: error: expected ',' after the first box corner, found '<'");
  CHECK(errorOf("cone { <0,0,0>, 1 <0,1,0>, 0 }") ==
        "s.pov:2:19: error: expected ',' after the cone base radius, found '<'");
  CHECK(errorOf("cone { <0,0,0>, 1, <0,1,0>, -2 }") ==
        "s.pov:2:29: error: the cone cap radius must not be negative, found -2");
  CHECK(errorOf("cylinder { <0,0,0> <0,1,0>, 1 }") ==
        "s.pov:2:20: error: expected ',' after the cylinder base, found '<'");
  CHECK(errorOf("plane { <0,1,0>, 1 pigment { rgb <1,1,1> } ior 2 }") ==
        "s.pov:2:44: error: unknown plane property 'ior'");
}

namespace {

// Everything a parse yields that a part of a file could get wrong: each object's location, shape, material
// and transform, the lights, the camera, the warnings. As bit patterns, so that equal means identical (and a
// large file compares in milliseconds).
std::string everything(const SceneDesc& s) {
  std::string out;
  const auto put = [&](double x) { out.append(reinterpret_cast<const char*>(&x), sizeof x); };
  const auto v = [&](const glm::dvec3& p) { put(p.x), put(p.y), put(p.z); };
  v(s.camera.location), v(s.camera.up), v(s.camera.right), v(s.camera.lookAt);
  for (const rt::LightDesc& l : s.lights) v(l.position), v(l.color);
  for (const rt::ObjectDesc& o : s.objects) {
    put(o.loc.line), put(o.loc.col), put(double(o.shape.index()));
    std::visit(
        [&](const auto& shape) {
          using S = std::decay_t<decltype(shape)>;
          if constexpr (std::is_same_v<S, rt::SphereDesc>) v(shape.center), put(shape.radius);
          if constexpr (std::is_same_v<S, rt::PlaneDesc>) v(shape.normal), put(shape.distance);
          if constexpr (std::is_same_v<S, rt::TriangleDesc>) v(shape.a), v(shape.b), v(shape.c);
          if constexpr (std::is_same_v<S, rt::BoxDesc>) v(shape.min), v(shape.max);
          if constexpr (std::is_same_v<S, rt::ConeDesc>) v(shape.base), v(shape.cap), put(shape.capRadius);
          if constexpr (std::is_same_v<S, rt::CylinderDesc>) v(shape.base), v(shape.cap), put(shape.radius);
        },
        o.shape);
    v(o.material.pigment), v(o.material.specular);
    v(glm::dvec3(o.worldFromObject()[3]));
    put(double(o.transforms.size()));
  }
  for (const std::string& w : s.warnings) out += "\n" + w;
  return out;
}

// About 1.25 MiB of statements in every layout: one-line and multi-line, indented, with line comments (some
// naming a shape), warnings to locate, and line ends of one kind (a line is `eol`).
std::string largeScene(const std::string& eol) {
  std::string s = "camera { location <0, 2, 10> look_at <0, 0, 0> }" + eol;
  s += "light_source { <10, 20, 30> color rgb <1, 1, 1> }" + eol;
  for (int i = 0; s.size() < (size_t(5) << 18); ++i) {
    const std::string n = std::to_string(i % 97) + "." + std::to_string(i % 10);
    switch (i % 5) {
      case 0: s += "sphere { <" + n + ", 0, -1>, 0.5 pigment { color rgb <1, 0.5, " + n + "> } }" + eol; break;
      case 1: s += "box {" + eol + "  <0, 0, 0>, <1, " + n + ", 1>" + eol + "  finish { metallic 1 }" + eol + "}" + eol; break;
      case 2: s += "  plane { <0, 1, 0>, -" + n + " } // sphere { <9, 9, 9>, 1 }" + eol; break;
      case 3: s += "// sphere { <8, 8, 8>, 1 }" + eol + "\tcone { <0, 0, 0>, 1, <0, " + n + ", 0>, 0 }" + eol; break;
      default: s += "cylinder { <0, 0, 0>, <0, 1, 0>, 0.5 translate <" + n + ", 0, 0> }" + eol; break;
    }
  }
  return s;
}

}  // namespace

TEST_CASE("pov: a large file reads the same on any number of threads, with any line ends") {
  for (const std::string eol : {"\n", "\r\n", "\r"}) {
    const std::string text = largeScene(eol);
    const std::string one = everything(parsePov(text, "big.pov", 1));
    CHECK(one.size() > 1000000);
    CHECK(everything(parsePov(text, "big.pov", 2)) == one);
    CHECK(everything(parsePov(text, "big.pov", 7)) == one);
  }
}

// Cuts fall where a keyword opens a line, which inside a block comment or a statement is no statement at all;
// and a second camera changes only what it names. Each reads as the whole file does.
TEST_CASE("pov: a large file whose keyword lines lie in comments, or with two cameras, reads as one piece") {
  std::string commented = largeScene("\n");
  commented.insert(commented.size() / 2, "/*\n" + largeScene("\n") + "*/\n");
  const std::string one = everything(parsePov(commented, "c.pov", 1));
  CHECK(parsePov(commented, "c.pov", 1).objects.size() == parsePov(largeScene("\n"), "c.pov", 1).objects.size());
  CHECK(everything(parsePov(commented, "c.pov", 4)) == one);

  const std::string cameras = largeScene("\n") + "camera { location <1, 2, 3> }\n";
  const SceneDesc s = parsePov(cameras, "d.pov", 4);
  CHECK(s.camera.location == glm::dvec3(1, 2, 3));
  CHECK(s.camera.lookAt == glm::dvec3(0, 0, 0));
  CHECK(everything(s) == everything(parsePov(cameras, "d.pov", 1)));
}

TEST_CASE("pov: an error in a large file is the error a one-piece read reports, on any number of threads") {
  const std::string text = largeScene("\n");
  const int lines = int(std::count(text.begin(), text.end(), '\n'));
  for (const auto& [bad, message] : std::vector<std::pair<std::string, std::string>>{
           {"sphere { <0, 0, 0>, -1 }\n", ":21: error: the sphere radius must be greater than 0, found -1"},
           {"/* never closed\n", ":1: error: comment '/*' is never closed"},
           {"box { <0, 0, 0> <1, 1, 1> }\n", ":17: error: expected ',' after the first box corner, found '<'"}}) {
    for (const size_t line : {text.find("\nsphere", text.size() / 3) + 1, text.size()}) {
      const std::string broken = text.substr(0, line) + bad + text.substr(line);
      const int lineNo = int(std::count(text.begin(), text.begin() + std::ptrdiff_t(line), '\n')) + 1;
      const std::string expected = "e.pov:" + std::to_string(lineNo) + message;
      for (const int threads : {1, 2, 5}) {
        INFO("line " << lineNo << " of " << lines << ", threads " << threads);
        CHECK_THROWS_WITH(parsePov(broken, "e.pov", threads), expected);
      }
    }
  }
}

// The argument for reading in parts (a part that reads to its end leaves the next cut between statements and
// outside comments) tried on seeded edits that keep the file valid but put line breaks, comments and
// statement-like lines where cuts may fall: between any two tokens, or at the start of a line. On any number
// of threads the scene is the one-piece read's.
TEST_CASE("pov: a large file with seeded comments and line breaks reads as one piece on any number of threads") {
  const std::string clean = largeScene("\n");
  const std::vector<std::string> betweenTokens{"\n", "\r\n", "\r", "/* sphere { */", "/*\nsphere { <1, 2, 3>, 1 }\n*/",
                                               "// }\n", "\n  \n"};
  const std::vector<std::string> lineStarts{"// sphere { <1, 1, 1>, 1 }\n", "/*\ncamera { location <9, 9, 9> }\n*/\n",
                                            "sphere { <5, 5, 5>, 0.5 }\n", "\n"};
  // Places in the clean text: spaces between tokens (outside the line comments), and the starts of lines that
  // start a statement (a letter in column 1).
  std::vector<size_t> spaces, starts;
  for (size_t at = 0, line = 0; at < clean.size(); ++at) {
    if (clean[at] == '\n') line = at + 1;
    if (clean[at] == ' ' && clean.substr(line, at - line).find("//") == std::string::npos) {
      spaces.push_back(at);
    }
    if (at == line && std::isalpha(static_cast<unsigned char>(clean[at]))) starts.push_back(at);
  }
  std::mt19937 rng(4730);
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<std::pair<size_t, std::string>> inserts;
    for (int k = 0; k < 40; ++k) {
      if (rng() % 2) {
        inserts.emplace_back(spaces[rng() % spaces.size()], betweenTokens[rng() % betweenTokens.size()]);
      } else {
        inserts.emplace_back(starts[rng() % starts.size()], lineStarts[rng() % lineStarts.size()]);
      }
    }
    std::sort(inserts.begin(), inserts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::string text = clean;
    for (const auto& [at, what] : inserts) text.insert(at, what);  // from the back, so places stay valid
    CAPTURE(trial);
    const std::string one = everything(parsePov(text, "r.pov", 1));
    CHECK(everything(parsePov(text, "r.pov", 2)) == one);
    CHECK(everything(parsePov(text, "r.pov", 5)) == one);
  }
}
