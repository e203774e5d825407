// The POV-Ray 3.7 language against values real POV-Ray 3.7 printed with #debug for the same lines.
#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <dirent.h>
#include <unistd.h>

#include "raytrace/parse/povray/interpreter.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/parse/scene_file.hpp"

namespace rt::povray {
namespace {

// What the scene's #debug lines print, or the error message it stops with.
std::string run(const std::string& text, const std::string& path = "scene.pov") {
  std::ostringstream out;
  InterpreterOptions options;
  options.debug = &out;
  Interpreter interpreter(options);
  try {
    interpreter.run(path, text, [](const std::shared_ptr<const Node>&) {}, [](const std::shared_ptr<const Node>&) {});
  } catch (const Error& e) {
    return out.str() + e.what();
  }
  return out.str();
}

std::string failure(const std::string& text, const std::string& path = "scene.pov") {
  try {
    parsePovRay(text, path, PovRayOptions{{}, 320, 240, false});
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

// A folder of its own for scenes with include files, removed afterwards.
struct Folder {
  std::string path;
  Folder() {
    char name[] = "/tmp/povray-test-XXXXXX";
    path = mkdtemp(name);
  }
  ~Folder() {
    for (const std::string& f : files) std::remove((path + "/" + f).c_str());
    rmdir(path.c_str());
  }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(path + "/" + name) << text;
    files.push_back(name);
  }
  std::vector<std::string> files;
};

TEST_CASE("povray: str, vstr and chr take any number, however far outside int's range", "[povray]") {
  // Found by fuzz_povray: a width or precision of 4e92 was converted to int (undefined behaviour). Width and
  // precision are held to ±200 digits, vstr's count to 1…5.
  const std::string scene = "#version 3.7;\n"
                            "#debug concat(\"[\", str(1.5, 0, 4e92), \"]\", str(1.5, 0, -4e92), \"|\", str(1.5, 1e300, 1), \"|\",\n"
                            "  str(1.5, -1e300, 1), \"|\", vstr(1e99, <1, 2>, \",\", 0, 0), \"|\", chr(65), \"\\n\")\n";
  const std::string digits(200, '0');
  CHECK(run(scene) == "[1.5" + digits.substr(1) + "]1.500000|" + std::string(197, ' ') + "1.5|" +
                          std::string(197, '0') + "1.5|1,2,0,0,0|A\n");
}

TEST_CASE("povray: built-in functions, operators, arrays, loops and conditions give POV-Ray's values", "[povray]") {
  const std::string scene = R"POV(#version 3.7;
#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} };
#debug concat(str(abs(-2.5),0,4)," ",str(acos(0.5),0,6)," ",str(asin(0.5),0,6)," ",str(atan2(1,2),0,6)," ",str(ceil(1.2),0,1)," ",str(floor(-1.2),0,1),"\n")
#debug concat(str(degrees(1),0,6)," ",str(radians(90),0,6)," ",str(exp(1),0,6)," ",str(ln(10),0,6)," ",str(log(1000),0,6)," ",str(sqrt(2),0,6),"\n")
#debug concat(str(max(1,5,3),0,0)," ",str(min(4,2,8),0,0)," ",str(select(-1,10,20),0,0)," ",str(select(0,10,20,30),0,0)," ",str(bitwise_and(12,10),0,0)," ",str(bitwise_or(12,10),0,0)," ",str(bitwise_xor(12,10),0,0),"\n")
#debug concat(str(vlength(<3,4,0>),0,3)," ",vstr(3,vnormalize(<3,0,4>),",",0,3)," ",str(vdot(<1,2,3>,<4,5,6>),0,1)," ",vstr(3,vcross(x,y),",",0,1),"\n")
#debug concat(vstr(3,vrotate(<1,0,0>,<0,0,90>),",",0,4)," ",vstr(3,vrotate(<1,2,3>,<30,40,50>),",",0,4)," ",vstr(3,vaxis_rotate(<1,0,0>,<0,1,0>,90),",",0,4),"\n")
#debug concat(chr(65),substr("hello",2,3),strupr("abc"),strlwr("DEF")," ",str(strlen("hello"),0,0)," ",str(asc("A"),0,0)," ",str(val("2.5"),0,2)," ",str(strcmp("a","b"),0,0),"\n")
#debug concat(str(dimensions(A),0,0)," ",str(dimension_size(A,2),0,0)," ",str(A[1][2],0,0)," ",str(defined(A),0,0)," ",str(defined(Nope),0,0),"\n")
#declare F = function(a, b) { a*b + 1 }
#debug concat(str(F(3,4),0,0)," ",str((2 > 1) + (1 >= 1) + (1 != 1) + (1 = 1),0,0)," ",str(!0,0,0)," ",str(<1,2,3>.y,0,0)," ",str(pi,0,8),"\n")
#for (I, 1, 10, 3) #debug str(I,0,0) #end #debug "\n"
#declare I = 0; #while (I < 3) #declare I = I + 1; #if (I = 2) #debug "two" #elseif (I = 3) #debug "three" #else #debug "one" #end #end #debug "\n"
#ifdef (A) #debug "A" #end #ifndef (B) #debug "noB" #end #debug "\n"
#debug concat(str(tan(1),0,6), " ", str(sinh(1),0,6), " ", str(cosh(1),0,6), " ", str(tanh(1),0,6), " ", str(asinh(1),0,6), " ", str(acosh(2),0,6), " ", str(atanh(0.5),0,6), " ", str(atan(1),0,6), "\n")
#debug concat(str(version,0,1), " ", str(int(3.7),0,0), " ", str(clock,0,0), " ", str(clock_delta,0,0), " ", str(initial_frame,0,0), " ", str(final_frame,0,0), "\n")
#declare C = rgbft <0.1,0.2,0.3,0.4,0.5>; #debug concat(str(C.red,0,1), str(C.green,0,1), str(C.blue,0,1), str(C.filter,0,1), str(C.transmit,0,1), " ", str(C.gray,0,4), "\n")
#declare D = color red 1 green 0.5 blue 0.25 transmit 0.5; #debug concat(vstr(5,D,",",0,2),"\n")
#declare E = <1,2,3>*2 - <1,1,1>/2; #debug concat(vstr(3,E,",",0,2),"\n")
#declare G = rgbt <1,0,0,0.5> * 0.5; #debug concat(vstr(5,G,",",0,2),"\n")
)POV";
  CHECK(run(scene) == R"(2.5000 1.047198 0.523599 0.463648 2.0 -2.0
57.295780 1.570796 2.718282 2.302585 3.000000 1.414214
5 2 10 20 8 14 6
5.000 0.600,0.000,0.800 32.0 0.0,0.0,1.0
0.0000,1.0000,0.0000 1.8013,2.5077,2.1135 0.0000,0.0000,-1.0000
AellABCdef 5 65 2.50 -1
2 3 6 1 0
13 3 1 2 3.14159265
14710
onetwothree
AnoB
1.557408 1.175201 1.543081 0.761594 0.881374 1.316958 0.549306 0.785398
3.7 3 0 0 0 0
0.10.20.30.40.5 0.1817
1.00,0.50,0.25,0.00,0.50
1.50,3.50,5.50
0.50,0.00,0.00,0.00,0.25
)");
}

TEST_CASE("povray: identifiers' levels, #break, loops, arrays and macros give POV-Ray's values", "[povray]") {
  CHECK(run(R"POV(#version 3.7;
#macro Set() #local V = 5; #declare V = 7; #debug concat(str(V,0,0), " ") #end
#declare V = 1; Set() #debug concat(str(V,0,0), "\n")
#macro Outer(A) #local B = A * 2; Inner() #end
#macro Inner() #debug concat("inner sees B=", str(B,0,0), "\n") #end
Outer(3)
#declare I = 0;
#while (I < 10) #declare I = I + 1; #if (I = 3) #break #end #end
#debug concat("I=", str(I,0,0), "\n")
#declare S = "";
#for (J, 5, 1, -2) #declare S = concat(S, str(J,0,0)); #end
#debug concat(S, "\n")
#declare Arr = array[3] {<1,2,3>, <4,5,6>, <7,8,9>};
#debug concat(vstr(3, Arr[1] + Arr[2], ",", 0, 0), "\n")
#macro Mk(R) sphere { 0, R } #end
#declare Obj = Mk(2)
#debug concat(str(dimension_size(Arr,1),0,0), "\n")
#declare C = <1,2,3>;
#declare C2 = C * <2,2,2> + 1;
#debug concat(vstr(3,C2,",",0,0), " ", str(vdot(C, C),0,0), "\n")
#local L = 9; #debug concat(str(L,0,0), "\n")
#declare Q = 2 * (3 + 4) - 10 / 4; #debug concat(str(Q,0,3), "\n")
#declare W = -<1,2>; #debug concat(vstr(2,W,",",0,0), "\n")
#declare F = 5; #declare F = F * F; #debug concat(str(F,0,0), "\n")
#debug concat(str(strlen(concat("ab", chr(67))),0,0), substr("abcdef", 3, 2), "\n")
#if (defined(Obj)) #debug "Obj\n" #end
#switch (3) #range (1, 2) #debug "low\n" #break #range (3, 4) #debug "mid\n" #break #else #debug "hi\n" #end
)POV") == R"(7 1
inner sees B=6
I=3
531
11,13,15
3
3,5,7 14
9
11.500
-1,-2
25
3cd
Obj
mid
)");
}

TEST_CASE("povray: directives end expressions where POV-Ray's do, and macros return into them", "[povray]") {
  CHECK(run(R"POV(#version 3.7;
#macro F(N) #if (N <= 1) 1 #else N * F(N - 1) #end #end
#debug concat(str(F(3) + 1, 0, 0), "\n")
#declare A = 0;
#if (A) #else #debug "else\n" #end
#if (1) #end
#while (A < 2) #declare A = A + 1; #end
#debug concat(str(A, 0, 0), "\n")
#if (1) #if (0) #else #debug "inner else\n" #end #end
#declare B = 2;
#if (B = 2) #declare C = 10; #else #declare C = 20; #end
#debug concat(str(C, 0, 0), "\n")
)POV") == R"(7
else
2
inner else
10
)");
}

TEST_CASE("povray: a macro returns a local array, which outlives the macro's scope", "[povray]") {
  // POV-Ray prints 4.0 twice.
  CHECK(run(R"(#version 3.7;
#macro M(N)
  #local A = array[N + 1][2]
  #local I = 0;
  #while (I <= N)
    #local A[I][0] = I;
    #local A[I][1] = 2 * I;
    #local I = I + 1;
  #end
  A
#end
#macro Use()
  #declare V = M(3)
  #debug concat(str(V[2][1], 0, 1), "\n")
#end
Use()
#declare W = M(2)
#debug concat(str(W[2][1], 0, 1), "\n")
)") == "4.0\n4.0\n");
}

TEST_CASE("povray: rand gives POV-Ray's sequence for each seed", "[povray]") {
  CHECK(run(R"(#declare R = seed(0); #declare S = seed(12345);
#debug concat(str(R,0,0), " ", str(S,0,0), "\n")
#for (I, 0, 2) #debug concat(str(rand(R),0,12), " ", str(rand(S),0,12), "\n") #end
#declare T = seed(-7); #debug concat(str(rand(T),0,12), "\n")
#declare T = seed(1.9); #debug concat(str(rand(T),0,12), "\n")
)") == "0 1\n0.000002874294 0.466563684509\n0.466563684509 0.249070228834\n0.249070228834 0.965876042136\n"
        "0.046072868175\n0.421992875268\n");
}

TEST_CASE("povray: #switch falls through to the next #case until #break", "[povray]") {
  CHECK(run("#declare A = 2;\n#switch (A)\n#case (1) #debug \"one\"\n#case (2) #debug \"two\"\n#case (3) "
            "#debug \"three\"\n#break\n#case (4) #debug \"four\"\n#end\n#switch (5) #range (4, 6) #debug \"range\" "
            "#break #else #debug \"else\" #end") == "twothreerange");
}

TEST_CASE("povray: macros: parameters by reference, use inside expressions, recursion and local identifiers", "[povray]") {
  CHECK(run("#macro M(P) #declare P = P + 1; #end #declare Q = 1; M(Q) #debug str(Q,0,0)") == "2");
  CHECK(run("#macro Add(A, B) A + B #end #debug str(Add(1,2)*3, 0, 0)") == "7");
  CHECK(run("#macro F(N) #if (N <= 1) 1 #else N * F(N - 1) #end #end #debug str(F(5), 0, 0)") == "120");
  CHECK(run("#declare L = 1; #macro S() #local L = 5; #debug str(L,0,0) #end S() #debug str(L,0,0)") == "51");
  const std::string deep = run("#macro R(N) R(N + 1) #end R(0)");
  CHECK(deep.rfind("scene.pov:1:13: error: macro calls nested more than 400 deep (in macro 'R' called from "
                   "scene.pov:1:13, ", 0) == 0);
  CHECK(deep.substr(deep.size() - 40) == "in macro 'R' called from scene.pov:1:27)");
}

TEST_CASE("povray: identifiers from the command line are numbers or strings, visible to #ifdef", "[povray]") {
  std::ostringstream out;
  InterpreterOptions options;
  options.debug = &out;
  Interpreter interpreter(options);
  interpreter.declare("Count", "12.5");
  interpreter.declare("Name", "tree");
  interpreter.run("scene.pov", "#ifdef (Count) #debug concat(str(Count * 2, 0, 1), Name) #end",
                  [](const std::shared_ptr<const Node>&) {}, [](const std::shared_ptr<const Node>&) {});
  CHECK(out.str() == "25.0tree");
}

TEST_CASE("povray: too deep a nesting is an error, not a stack overflow", "[povray]") {
  CHECK(run("#declare A = " + std::string(5000, '(') + "1" + std::string(5000, ')') + ";") ==
        "scene.pov:1:270: error: expressions or blocks nested more than 256 deep");
  CHECK(run("#declare A = " + std::string(100000, '-') + "1;") ==
        "scene.pov:1:270: error: expressions or blocks nested more than 256 deep");
  CHECK(failure("#declare A = sphere { 0, 1 }\n#for (I, 1, 5000) #declare A = object { A } #end\nobject { A }\n") ==
        "scene.pov:2:41: error: objects or blocks nested more than 256 deep");
}

TEST_CASE("povray: #local in an include file ends with the file, even as its last line", "[povray]") {
  Folder folder;
  folder.write("local.inc", "#local Thing = 2;\n#local Item = cylinder { -1, 1, 1 }");
  CHECK(run("#declare Thing = 1;\n#include \"local.inc\"\n#ifdef (Item) #debug \"found\" #else #debug \"gone\" #end\n"
            "#debug str(Thing, 0, 0)", folder.path + "/scene.pov") == "gone1");
}

TEST_CASE("povray: a declaration without a semicolon ends before the next directive", "[povray]") {
  CHECK(run("#declare A = array[2]\n#declare A[0] = 3\n#declare A[1] = A[0] * 2\n#debug str(A[1],0,0)") == "6");
}

TEST_CASE("povray: an error in an include file or a macro names the chain of places", "[povray]") {
  Folder folder;
  folder.write("inner.inc", "#declare A = 1;\n  #declare B = Nope;\n");
  folder.write("scene.pov", "#version 3.7;\n#include \"inner.inc\"\n");
  CHECK(failure("#version 3.7;\n\n\n#include \"inner.inc\"\n", folder.path + "/scene.pov") ==
        "inner.inc:2:16: error: undeclared identifier 'Nope' (included from " + folder.path + "/scene.pov:4:1)");
  CHECK(failure("#macro Tree(H)\n  sphere { 0, H pigment { Bad } }\n#end\n\n  Tree(1)\n") ==
        "scene.pov:2:27: error: undeclared identifier 'Bad' (in macro 'Tree' called from scene.pov:5:3)");
  folder.write("self.inc", "#include \"self.inc\"\n");
  const std::string deep = failure("#include \"self.inc\"\n", folder.path + "/scene.pov");
  CHECK(deep.rfind("self.inc:1:1: error: include files nested more than 64 deep (included from self.inc:1:1, ", 0) == 0);
  CHECK(failure("#include \"missing.inc\"") == "scene.pov:1:1: error: cannot find the include file 'missing.inc'");
  CHECK(failure("#error \"stop here\"") == "scene.pov:1:1: error: stop here");
  CHECK(failure("#if (1)\nsphere { 0, 1 }\n") ==
        "scene.pov:3:1: error: a directive is still open at the end of the file: #end is missing");
}

TEST_CASE("povray: each directive is told by its name, and an unknown one is an error", "[povray]") {
  CHECK(failure("#version 3.7;\n  #whilst (1)\n") == "scene.pov:2:3: error: unknown directive '#whilst'");
  CHECK(failure("#elseif (1)\n") == "scene.pov:1:1: error: #elseif without #if");
  CHECK(failure("#range (1, 2)\n") == "scene.pov:1:1: error: #range without #switch");
  // A skipped branch's nested #if, #while and #switch each close with their own #end.
  CHECK(run("#if (0) #if (1) #while (0) #end #switch (1) #case (1) #break #end #end #debug \"a\" "
            "#elseif (1) #debug \"b\" #else #debug \"c\" #end") == "b");
  CHECK(run("#ifndef (Nope) #debug \"none\" #end #local L = 1; #undef L #ifdef (L) #debug \"still\" #end") == "none");
}

TEST_CASE("povray: what cannot be drawn yet is refused as not supported, after the whole file has parsed", "[povray]") {
  CHECK(failure("#version 3.7;\n  ovus { 1, 0.5 }\n") == "scene.pov:2:3: error: 'ovus' is not supported yet");
  CHECK(failure("#version 3.7;\nsphere { 0, 1 pigment { square } }\n") ==
        "scene.pov:2:25: error: 'square' is not supported yet");
  // A typo later in the file is still a typo.
  CHECK(failure("#version 3.7;\nsuperellipsoid { <1, 0.5> }\nsphere { 0, 1 pigment { Rde } }\n") ==
        "scene.pov:3:25: error: undeclared identifier 'Rde'");
}

TEST_CASE("povray: the scene: camera by POV-Ray's rules, lights, shapes, colours and transforms", "[povray]") {
  const SceneDesc s = parsePovRay(R"(#version 3.7;
#include "colors.inc"
camera { location <0, 0, -5> look_at <0, 0, 0> angle 90 }
light_source { <1, 2, 3>, color White translate x }
sphere { <0, 1, 0>, 2 pigment { color Red } finish { ambient 0.2 diffuse 0.5 } rotate <90, 0, 0> scale 2 }
box { <1, 1, 1>, <0, 0, 0> pigment { rgbf <0, 0, 1, 0.5> } }
)", "scene.pov", PovRayOptions{{}, 320, 240, false});
  CHECK(s.language == SceneLanguage::PovRay);
  CHECK(s.camera.location == glm::dvec3(0, 0, -5));
  CHECK(s.camera.lookAt == glm::dvec3(0, 0, -4));
  // angle 90: the direction's length is half the right vector's, 1.33 / 2; right and up are divided by it.
  CHECK(s.camera.right.x == Approx(2).epsilon(1e-12));
  CHECK(s.camera.up.y == Approx(2 / 1.33).epsilon(1e-12));
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].position == glm::dvec3(2, 2, 3));
  REQUIRE(s.objects.size() == 2);
  CHECK(std::get<SphereDesc>(s.objects[0].shape).radius == 2);
  CHECK(s.objects[0].material.pigment == Color(1, 0, 0));
  CHECK(s.objects[0].material.ambient == Color(0.2f, 0, 0));
  CHECK(s.objects[0].material.diffuse == Color(0.5f, 0, 0));
  REQUIRE(s.objects[0].transforms.size() == 2);
  CHECK(s.objects[0].transforms[0].v == glm::dvec3(90, 0, 0));
  CHECK(s.objects[0].transforms[1].v == glm::dvec3(2, 2, 2));
  CHECK(std::get<BoxDesc>(s.objects[1].shape).min == glm::dvec3(0));
  CHECK(s.objects[1].material.filter == 0.5f);
  CHECK(s.objects[1].material.ambient == Color(0, 0, 0.1f));  // POV-Ray's default finish
}

TEST_CASE("povray: a .pov file is POV-Ray 3.7 when it uses a directive or global_settings", "[povray]") {
  CHECK(usesPovRayLanguage("#version 3.7;"));
  CHECK(usesPovRayLanguage("camera {}\n  # declare A = 1;"));
  CHECK(usesPovRayLanguage("global_settings { assumed_gamma 1 }"));
  CHECK_FALSE(usesPovRayLanguage("// #include \"colors.inc\"\ncamera { location <0,0,5> }"));
  CHECK_FALSE(usesPovRayLanguage("/* #declare */ sphere { <0,0,0>, 1 pigment { color rgb <1,0,0> } }"));
  CHECK_FALSE(usesPovRayLanguage("my_global_settings"));
  // --dialect overrides the rule either way.
  CHECK(povDialect("camera {}", DialectChoice::Auto) == SceneLanguage::Pov);
  CHECK(povDialect("#version 3.7;", DialectChoice::Auto) == SceneLanguage::PovRay);
  CHECK(povDialect("#version 3.7;", DialectChoice::Course) == SceneLanguage::Pov);
  CHECK(povDialect("camera {}", DialectChoice::PovRay) == SceneLanguage::PovRay);
}

TEST_CASE("povray: every file of POV-Ray's standard include library parses when included", "[povray]") {
  const std::string folder = "/usr/share/povray-3.7/include";
  DIR* dir = opendir(folder.c_str());
  if (!dir) {
    WARN("POV-Ray's include library is not installed (apt-get install povray-includes): skipped");
    return;
  }
  std::vector<std::string> names;
  while (const dirent* e = readdir(dir)) {
    const std::string n = e->d_name;
    if (n.size() > 4 && n.substr(n.size() - 4) == ".inc") names.push_back(n);
  }
  closedir(dir);
  CHECK(names.size() > 30);
  for (const std::string& n : names) {
    INFO(n);
    // colors.inc and shapes.inc first, as the files that use their names expect.
    const std::string out = run("#version 3.7;\n#include \"colors.inc\"\n#include \"shapes.inc\"\n#include \"" + n + "\"\n");
    CHECK_FALSE(out.find(": error: ") != std::string::npos);
    if (out.find(": error: ") != std::string::npos) FAIL_CHECK(out);
  }
}

TEST_CASE("povray: the lexer marks each built-in word with its place among the built-ins by name", "[povray]") {
  CHECK(builtinIndex("abs") == 1);
  CHECK(builtinIndex("acos") == 2);
  CHECK(builtinIndex("z") == 90);
  CHECK(builtinIndex("sphere") == 0);
  CHECK(builtinIndex("Rand") == 0);
  TokenFile file;
  lex("rand(R) sphere z", file);
  REQUIRE(file.tokens.size() == 7);
  CHECK(int(file.tokens[0].builtin) == builtinIndex("rand"));
  CHECK(file.tokens[0].builtin != 0);
  CHECK(file.tokens[2].builtin == 0);  // an identifier
  CHECK(file.tokens[4].builtin == 0);  // a keyword that is no built-in
  CHECK(file.tokens[5].builtin == 90);
}

}  // namespace
}  // namespace rt::povray
