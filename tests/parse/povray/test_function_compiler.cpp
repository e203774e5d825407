// User functions compiled once (parse/povray/function_compiler.cpp, surface/function.hpp): values computed by
// hand, and functions.inc's internal functions against what POV-Ray 3.7 printed for the same calls.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

#include "raytrace/parse/povray/interpreter.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/surface/function.hpp"

namespace rt::povray {
namespace {

std::string run(const std::string& text) {
  std::ostringstream out;
  InterpreterOptions options;
  options.debug = &out;
  Interpreter interpreter(options);
  try {
    interpreter.run("scene.pov", text, [](const std::shared_ptr<const Node>&) {}, [](const std::shared_ptr<const Node>&) {});
  } catch (const Error& e) {
    return out.str() + e.what();
  }
  return out.str();
}

// The compiled function a `#declare F = function … ` line makes, through the statement that uses it.
std::shared_ptr<const FunctionValue> declared(const std::string& declaration) {
  std::shared_ptr<const FunctionValue> f;
  Interpreter interpreter(InterpreterOptions{});
  interpreter.run("scene.pov", declaration + "\nsphere { 0, 1 pigment { function { F(x, y, z) } } }\n",
                  [&](const std::shared_ptr<const Node>& n) {
                    const Node& pigment = *n->items.back().node;
                    f = std::static_pointer_cast<const FunctionValue>(pigment.items.front().value.ref);
                  },
                  [](const std::shared_ptr<const Node>&) {});
  return f;
}

double at(const std::string& body, double x, double y = 0, double z = 0) {
  const auto f = declared("#declare K = 3;\n#declare V = <4, 5, 6>;\n#declare F = function " + body);
  REQUIRE(f->compiled);
  return f->compiled->at({x, y, z});
}

}  // namespace

TEST_CASE("a compiled function keeps the precedence of POV-Ray's expressions", "[function]") {
  CHECK(at("{ 2 * x + 3 * y - z / 4 }", 1, 2, 3) == 7.25);
  CHECK(at("{ -x * x + 2 }", 3) == -7);
  CHECK(at("{ 10 - 4 - 3 }", 0) == 3);
  CHECK(at("{ 12 / 3 / 2 }", 0) == 2);
  CHECK(at("{ (1 + 2) * (x - 1) }", 3) == 6);
  CHECK(at("{ 1 + 2 < 4 }", 0) == 1);
  CHECK(at("{ x < 1 | x > 2 & y }", 3, 0) == 0);
  CHECK(at("{ x < 1 | x > 2 & y }", 0.5, 1) == 1);
  CHECK(at("{ !x + !0 }", 2) == 1);
  CHECK(at("{ x = 1 }", 1 + 1e-12) == 0);  // exact, as POV-Ray's functions compare
  CHECK(at("{ x != 1 }", 1 + 1e-12) == 1);
  CHECK(at("{ (x <= 2) + (x >= 2) }", 2) == 2);
  CHECK(at("{ x > 0 ? 10 : 20 }", -1) == 20);
}

TEST_CASE("a compiled function computes every float built-in", "[function]") {
  const double x = 0.3;
  CHECK(at("{ sin(x) }", x) == std::sin(x));
  CHECK(at("{ cos(x) }", x) == std::cos(x));
  CHECK(at("{ tan(x) }", x) == std::tan(x));
  CHECK(at("{ asin(x) }", x) == std::asin(x));
  CHECK(at("{ acos(x) }", x) == std::acos(x));
  CHECK(at("{ atan(x) }", x) == std::atan(x));
  CHECK(at("{ atan2(x, y) }", 1, 2) == std::atan2(1.0, 2.0));
  CHECK(at("{ sinh(x) }", x) == std::sinh(x));
  CHECK(at("{ cosh(x) }", x) == std::cosh(x));
  CHECK(at("{ tanh(x) }", x) == std::tanh(x));
  CHECK(at("{ asinh(x) }", x) == std::asinh(x));
  CHECK(at("{ acosh(x) }", 2) == Approx(std::acosh(2.0)).epsilon(1e-15));  // the test's own is folded exactly
  CHECK(at("{ atanh(x) }", x) == Approx(std::atanh(x)).epsilon(1e-15));
  CHECK(at("{ exp(x) }", x) == std::exp(x));
  CHECK(at("{ ln(x) }", 100) == std::log(100.0));
  CHECK(at("{ log(x) }", 100) == 2);
  CHECK(at("{ pow(x, y) }", 2, 10) == 1024);
  CHECK(at("{ sqrt(x) }", 2) == std::sqrt(2.0));
  CHECK(at("{ abs(x) }", -2.5) == 2.5);
  CHECK(at("{ min(x, y, 1) }", 3, 2) == 1);
  CHECK(at("{ max(x, y) }", 3, 2) == 3);
  CHECK(at("{ floor(x) }", -1.5) == -2);
  CHECK(at("{ ceil(x) }", -1.5) == -1);
  CHECK(at("{ int(x) }", -7.5) == -7);   // POV-Ray: -7
  CHECK(at("{ mod(x, 2) }", -7.5) == -1.5);  // POV-Ray: -1.5
  CHECK(at("{ select(x, 1, 2) }", 0) == 2);
  CHECK(at("{ select(x, 1, 2, 3) }", 0) == 2);
  CHECK(at("{ select(x, 1, 2, 3) }", 1e-12) == 3);
  CHECK(at("{ select(x, 1, 2, 3) }", -1) == 1);
  CHECK(at("{ degrees(x) }", 3.14159265358979323846) == Approx(180).epsilon(1e-15));
  CHECK(at("{ radians(x) }", 180) == Approx(3.14159265358979323846).epsilon(1e-15));
  CHECK(at("{ pi + true + false }", 0) == 3.14159265358979323846 + 1);
}

TEST_CASE("a compiled function reads its parameters, u and v, identifiers and other functions", "[function]") {
  CHECK(at("{ u + 10 * v }", 1, 2, 3) == 21);  // POV-Ray: 21
  CHECK(at("{ K * x + V.y }", 2) == 11);
  CHECK(at("{ x + clock + image_width }", 2) == 322);  // clock 0, the test's width 320
  const auto f = declared("#declare G = function(a, b) { a - b }\n#declare F = function { G(x, 1) * G(y) }");
  REQUIRE(f->compiled);
  CHECK(f->compiled->at({3, 4, 0}) == 8);
  // A declared float is taken where the function is declared.
  CHECK(run("#declare K = 1;\n#declare F = function { x + K }\n#declare K = 5;\n#debug str(F(1, 0, 0), 0, 1)\n") == "2.0");
}

TEST_CASE("functions.inc's internal functions give POV-Ray's values", "[function]") {
  const std::string inc = "#include \"/usr/share/povray-3.7/include/functions.inc\"\n";
  const auto value = [&](const std::string& call) {
    return std::stod(run(inc + "#debug str(" + call + ", 0, 12)\n"));
  };
  // What POV-Ray 3.7 printed with str(…, 0, 12).
  CHECK(value("f_sphere(1, 2, 3, 1)") == Approx(2.741657386774).margin(1e-12));
  CHECK(value("f_torus(1, 2, 3, 1, 0.5)") == Approx(2.445410782839).margin(1e-12));
  CHECK(value("f_noise3d(0.3, 0.7, 1.1)") == Approx(0.689585217264).margin(1e-12));
  CHECK(value("f_snoise3d(0.3, 0.7, 1.1)") == Approx(0.379170434528).margin(1e-12));
  CHECK(value("f_noise_generator(0.3, 0.7, 1.1, 1)") == Approx(0.855310987588).margin(1e-12));
  CHECK(value("f_noise_generator(0.3, 0.7, 1.1, 3)") == Approx(0.573302353883).margin(1e-12));
  CHECK(value("f_rounded_box(1, 2, 3, 0.2, 0.5, 0.6, 0.7)") == Approx(2.849589136395).margin(1e-12));
  CHECK(value("f_rounded_box(0.1, 0.2, 0.3, 0.2, 0.5, 0.6, 0.7)") == Approx(-0.200001).margin(1e-12));
  CHECK(value("f_rounded_box(0.45, 0.5, 0.3, 0.2, 0.5, 0.6, 0.7)") == Approx(-0.019723436227).margin(1e-12));
  CHECK(value("f_superellipsoid(0.3, 0.4, 0.5, 0.5, 0.25)") == Approx(0.483792025729).margin(1e-12));
  CHECK(value("f_r(0.3, -0.4, 1.2)") == Approx(1.3).margin(1e-12));
  CHECK(value("f_th(0.3, -0.4, 1.2)") == Approx(0.244978663127).margin(1e-12));
  CHECK(value("f_th(-0.3, -0.4, -1.2)") == Approx(-2.896613990463).margin(1e-12));
  CHECK(value("f_ph(0.3, -0.4, 1.2)") == Approx(1.883563048736).margin(1e-12));
  CHECK(value("f_ph(-0.3, 0.4, -1.2)") == Approx(1.258029604853).margin(1e-12));
  CHECK(value("f_ellipsoid(0.3, -0.4, 1.2, 1, 2, 3)") == Approx(3.7).margin(1e-12));
  CHECK(value("f_sine_wave(0.3, 2, 1.5)") == Approx(1.975376681190).margin(1e-12));
}

TEST_CASE("a function that does not compile is refused where it is drawn", "[function]") {
  const auto failure = [](const std::string& text) {
    try {
      parsePovRay("#version 3.7;\n#include \"/usr/share/povray-3.7/include/functions.inc\"\n" + text, "scene.pov",
                  PovRayOptions{{}, 320, 240, false});
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(failure("isosurface { function { f_helix1(x, y, z, 1, 2, 3, 4, 5, 6, 7) } }\n") ==
        "scene.pov:3:25: error: 'f_helix1' is not supported yet");
  CHECK(failure("#declare f_square = function { pattern { square } }\n"
                "sphere { 0, 1 pigment { function { f_square(x, y, z) } } }\n") ==
        "scene.pov:4:36: error: 'f_square' is not supported yet");
  CHECK(failure("isosurface { function { internal(25) } }\n") ==
        "scene.pov:3:25: error: 'internal(25)' is not supported yet");
}

}  // namespace rt::povray

namespace rt::povray {

TEST_CASE("a pattern function returns the pattern's value with its modifiers, as POV-Ray's does", "[function]") {
  const SceneDesc s = parsePovRay(R"(#version 3.7;
#declare A = function { pattern { gradient x } }
#declare B = function { pattern { gradient x triangle_wave } }
#declare C = function { pattern { gradient x scale 2 frequency 2 } }
#declare D = function { pattern { bozo scale <7, 1, 2> } }
#declare E = function { pattern { marble } }
#fopen F "values.txt" write
#write (F, str(A(1.5, 0, 0), 0, 12), " ", str(A(-0.25, 0, 0), 0, 12), " ", str(B(0.75, 0, 0), 0, 12), " ",
        str(C(0.75, 0, 0), 0, 12), " ", str(D(0.3, 0.7, 1.1), 0, 12), " ", str(E(0.3, 0.7, 1.1), 0, 12))
#fclose F
)", "scene.pov", PovRayOptions{{}, 320, 240, false});
  REQUIRE(s.dataFiles.size() == 1);
  // What POV-Ray 3.7 printed for the same calls; the noise agrees to about 1e-11 (docs/povray-noise.md).
  const double povray[] = {0.5, 0.75, 0.5, 0.75, 0.490511685881, 0.6};
  std::istringstream in(s.dataFiles[0].text);
  for (double expected : povray) {
    double v = -1;
    in >> v;
    CHECK(v == Approx(expected).margin(1e-11));
  }
}

}  // namespace rt::povray

namespace rt::povray {

namespace {

SceneDesc withPigmentFunction(const std::string& text) {
  return parsePovRay("#version 3.7;\n#declare P = pigment { gradient x color_map { [0 rgbft <0, 0.2, 0.4, 0.1, 0.3>] "
                     "[1 rgbft <1, 0.6, 0.8, 0.5, 0.7>] } }\n#declare F = function { pigment { P } }\n" + text,
                     "scene.pov", PovRayOptions{{}, 320, 240, false});
}

std::string pigmentFunctionFailure(const std::string& text) {
  try {
    withPigmentFunction(text);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("a pigment function's components are its colour's at the point, as POV-Ray's are", "[function]") {
  // At x = 0.25 the map is a quarter of the way: rgbft <0.25, 0.3, 0.5, 0.2, 0.4>; gray is 0.297 red +
  // 0.589 green + 0.114 blue = 0.30795. POV-Ray 3.7 printed the same for each component.
  const SceneDesc s = withPigmentFunction(R"(
#declare G = function(c) { select(c - 1, F(x, y, z).x, F(x, y, z).red, F(x, y, z).u) }
#declare Components = array[13] {
  function { F(x, y, z).x }, function { F(x, y, z).y }, function { F(x, y, z).z },
  function { F(x, y, z).red }, function { F(x, y, z).green }, function { F(x, y, z).blue },
  function { F(x, y, z).filter }, function { F(x, y, z).transmit }, function { F(x, y, z).t },
  function { F(x, y, z).u }, function { F(x, y, z).v }, function { F(x, y, z).gray }, function { F(x).grey } }
#fopen O "values.txt" write
#for (I, 0, 12)
  #local C = Components[I];
  #write (O, str(C(0.25, 0, 0), 0, 9), " ")
#end
#write (O, vstr(5, F(0.25, 7, 9), " ", 0, 9))
#fclose O
sphere { 0, 1 pigment { function { F(x, y, z).gray * 2 } } }
)");
  REQUIRE(s.dataFiles.size() == 1);
  const double expected[] = {0.25, 0.3, 0.5, 0.25, 0.3, 0.5, 0.2, 0.4, 0.2, 0.25, 0.3, 0.30795, 0.30795,
                             0.25, 0.3, 0.5, 0.2, 0.4};
  std::istringstream in(s.dataFiles[0].text);
  for (double e : expected) {
    double v = -1;
    in >> v;
    CHECK(v == Approx(e).margin(1e-6));  // the colours are single precision
  }
}

TEST_CASE("a pigment function's pigment keeps its transforms", "[function]") {
  const SceneDesc s = withPigmentFunction(R"(
#declare H = function { pigment { P scale 2 } }
#declare K = function { H(x, y, z).red + H(x, y, z).blue }
#fopen O "values.txt" write
#write (O, str(K(0.5, 0, 0), 0, 9))
#fclose O
)");
  REQUIRE(s.dataFiles.size() == 1);
  CHECK(std::stod(s.dataFiles[0].text) == Approx(0.25 + 0.5).margin(1e-6));  // the map at x = 0.25
}

TEST_CASE("a pigment function's call without a component is refused as POV-Ray refuses it", "[function]") {
  CHECK(pigmentFunctionFailure("#declare G = function { F(x, y, z) + 1 }\n") ==
        "scene.pov:4:36: error: expected '.' and a component after the pigment function's call");
  CHECK(pigmentFunctionFailure("#declare G = function { F(x, y, z).hf }\n") ==
        "scene.pov:4:36: error: unknown component '.hf' of a colour");
}

TEST_CASE("a pigment function raytrace does not draw is refused where it is drawn", "[function]") {
  CHECK(pigmentFunctionFailure("sphere { 0, 1 pigment { function { F(x, y, z, 1).x } } }\n") ==
        "scene.pov:4:36: error: 'F with too many arguments' is not supported yet");
  // The refused pigment is named where it is, whether drawn through a function or called in SDL.
  CHECK(pigmentFunctionFailure("#declare Q = function { pigment { spiral1 2 turbulence 0.3 } }\n"
                               "sphere { 0, 1 pigment { function { Q(x, y, z).x } } }\n") ==
        "scene.pov:4:25: error: 'turbulence on spiral1' is not supported yet");
  CHECK(pigmentFunctionFailure("#declare Q = function { pigment { spiral1 2 turbulence 0.3 } }\n"
                               "#declare V = Q(1, 2, 3);\n") ==
        "scene.pov:4:25: error: 'turbulence on spiral1' is not supported yet");
}

}  // namespace rt::povray
