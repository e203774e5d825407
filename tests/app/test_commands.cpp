// The command line through runCommand with string streams: usage, every argument error with its whole
// message, and the Program 1 commands on a scene written by the test.
#include <catch2/catch.hpp>

#include <sstream>

#include "raytrace/app/arguments.hpp"
#include "raytrace/app/commands.hpp"
#include "raytrace/util/error.hpp"
#include "temp_dir.hpp"

namespace {

// The error message a command line produces, or "" if it runs.
std::string errorOf(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  try {
    rt::runCommand(args, out, err);
  } catch (const rt::Error& e) {
    return e.what();
  }
  return "";
}

struct Run {
  int status;
  std::string out, err;
};

Run run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int status = rt::runCommand(args, out, err);
  return {status, out.str(), err.str()};
}

const char* const kScene =
    "camera { location <0,0,14> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
    "light_source { <-100,100,100> color rgb <1.5,1.5,1.5> }\n"
    "sphere { <0,0,0>, 2 pigment { color rgb <1,0,1> } finish { ambient 0.2 diffuse 0.4 metallic 1 } }\n"
    "plane { <0,1,0>, -4 pigment { color rgb <0.2,0.2,0.8> } finish { ambient 0.4 diffuse 0.8 } }\n";

}  // namespace

TEST_CASE("cli: usage lists every Program 1 command") {
  const std::string u = rt::usage();
  CHECK(u.find("raytrace raycast <scene> <width> <height> [options]") != std::string::npos);
  CHECK(u.find("raytrace sceneinfo <scene> [options]") != std::string::npos);
  CHECK(u.find("raytrace pixelray <scene> <width> <height> <x> <y> [options]") != std::string::npos);
  CHECK(u.find("raytrace firsthit <scene> <width> <height> <x> <y> [options]") != std::string::npos);
  for (const char* help : {"--help", "-h"}) {
    const Run r = run({help});
    CHECK(r.status == 0);
    CHECK(r.out == u);
    CHECK(r.err.empty());
  }
}

TEST_CASE("cli: no command, an unknown command, an unknown option") {
  CHECK(errorOf({}) == "no command given\n" + rt::usage());
  CHECK(errorOf({"render2", "a.pov"}) == "unknown command 'render2'\n" + rt::usage());
  CHECK(errorOf({"sceneinfo", "a.pov", "--fast"}) == "unknown option '--fast' (see raytrace --help)");
  CHECK(errorOf({"sceneinfo", "a.pov", "--precision=quad"}) == "--precision must be float, double, course or auto, found 'quad'");
  CHECK(errorOf({"sceneinfo", "a.pov", "--sphere=fast"}) == "--sphere must be textbook, robust or auto, found 'fast'");
}

TEST_CASE("cli: the -gi flags and their bad values") {
  CHECK(errorOf({"render", "a.pov", "-gi_samples=64,x"}) == "-gi_samples must be a whole number, found 'x'");
  CHECK(errorOf({"render", "a.pov", "-gi_samples=64,"}) == "-gi_samples must be a whole number, found ''");
  CHECK(errorOf({"render", "a.pov", "-gi_samples=0"}) == "-gi_samples must be between 1 and 65536, found 0");
  CHECK(errorOf({"render", "a.pov", "-gi_bounces=17"}) == "-gi_bounces must be between 0 and 16, found 17");
  CHECK(errorOf({"render", "a.pov", "--seed"}) == "--seed needs a number");
  CHECK(errorOf({"render", "a.pov", "--seed=-1"}) == "--seed must be between 0 and 2147483647, found -1");
  CHECK(errorOf({"render", "a.pov", "--gi-adaptive=0"}) ==
        "--gi-adaptive must be a number above 0 and at most 1, found '0'");
  CHECK(errorOf({"render", "a.pov", "--gi-adaptive=0.1x"}) ==
        "--gi-adaptive must be a number above 0 and at most 1, found '0.1x'");
  const rt::RenderOptions o = rt::parseFlag("-gi_bounces=3", rt::parseFlag("-gi_samples=32,8", rt::parseFlag("-gi", {})));
  CHECK(o.gi.enabled);
  CHECK(o.gi.samples == std::vector<int>{32, 8});
  CHECK(o.gi.bounceCount() == 3);
  CHECK(o.gi.samplesAt(2) == 8);
}

TEST_CASE("cli: wrong argument counts") {
  CHECK(errorOf({"sceneinfo"}) == "sceneinfo takes 1 arguments, found 0\nusage: raytrace sceneinfo <scene>");
  CHECK(errorOf({"sceneinfo", "a.pov", "640"}) ==
        "sceneinfo takes 1 arguments, found 2\nusage: raytrace sceneinfo <scene>");
  CHECK(errorOf({"raycast", "a.pov", "640"}) ==
        "raycast takes 3 arguments, found 2\nusage: raytrace raycast <scene> <width> <height>");
  CHECK(errorOf({"pixelray", "a.pov", "640", "480"}) ==
        "pixelray takes 5 arguments, found 3\nusage: raytrace pixelray <scene> <width> <height> <x> <y>");
  CHECK(errorOf({"firsthit", "a.pov", "640", "480", "1", "2", "3"}) ==
        "firsthit takes 5 arguments, found 6\nusage: raytrace firsthit <scene> <width> <height> <x> <y>");
}

TEST_CASE("cli: width and height must be whole numbers in range, checked before the scene is read") {
  CHECK(errorOf({"raycast", "missing.pov", "abc", "480"}) == "width must be a whole number, found 'abc'");
  CHECK(errorOf({"raycast", "missing.pov", "640.5", "480"}) == "width must be a whole number, found '640.5'");
  CHECK(errorOf({"raycast", "missing.pov", "", "480"}) == "width must be a whole number, found ''");
  CHECK(errorOf({"raycast", "missing.pov", "640", "4x"}) == "height must be a whole number, found '4x'");
  CHECK(errorOf({"raycast", "missing.pov", "0", "480"}) == "width must be between 1 and 32768, found 0");
  CHECK(errorOf({"raycast", "missing.pov", "-640", "480"}) == "width must be between 1 and 32768, found -640");
  CHECK(errorOf({"raycast", "missing.pov", "640", "-1"}) == "height must be between 1 and 32768, found -1");
  CHECK(errorOf({"raycast", "missing.pov", "32769", "480"}) == "width must be between 1 and 32768, found 32769");
  CHECK(errorOf({"raycast", "missing.pov", "640", "99999999999999999999999"}) ==
        "height must be between 1 and 32768, found 99999999999999999999999");
}

TEST_CASE("cli: the pixel must lie inside the image") {
  CHECK(errorOf({"pixelray", "missing.pov", "640", "480", "640", "0"}) ==
        "pixel x must be between 0 and 639, found 640");
  CHECK(errorOf({"pixelray", "missing.pov", "640", "480", "0", "480"}) ==
        "pixel y must be between 0 and 479, found 480");
  CHECK(errorOf({"firsthit", "missing.pov", "640", "480", "-1", "0"}) == "pixel x must be between 0 and 639, found -1");
  CHECK(errorOf({"firsthit", "missing.pov", "640", "480", "1", "y"}) == "pixel y must be a whole number, found 'y'");
}

TEST_CASE("cli: a missing scene, a directory, a scene with an error") {
  const rt::test::TempDir dir;
  const std::string missing = dir.file("nope.pov");
  CHECK(errorOf({"sceneinfo", missing}) == "cannot open '" + missing + "': No such file or directory");
  CHECK(errorOf({"sceneinfo", dir.path()}) == "cannot read '" + dir.path() + "': it is a directory, not a scene file");
  const std::string bad = dir.write("bad.pov", "camera {}\nsphere { <0,0,0>, 0 }\n");
  CHECK(errorOf({"firsthit", bad, "4", "4", "1", "1"}) ==
        bad + ":2:19: error: the sphere radius must be greater than 0, found 0");
}

TEST_CASE("cli: sceneinfo prints the scene; warnings go to the error stream") {
  const rt::test::TempDir dir;
  const std::string scene = dir.write("s.pov", kScene);
  const Run r = run({"sceneinfo", scene});
  CHECK(r.status == 0);
  CHECK(r.err == scene + ":3:84: warning: 'metallic' is not modelled and is ignored\n");
  CHECK(r.out.rfind("Camera:\n- Location: {0.0000 0.0000 14.0000}\n- Up: {0.0000 1.0000 0.0000}\n"
                    "- Right: {1.3333 0.0000 0.0000}\n- Look at: {0.0000 0.0000 0.0000}\n\n---\n\n1 light(s)\n",
                    0) == 0);
  CHECK(r.out.find("Object[1]:\n- Type: Plane\n- Normal: {0.0000 1.0000 0.0000}\n- Distance: -4.0000\n"
                   "- Color: {0.2000 0.2000 0.8000}\n- Material:\n  - Ambient: 0.4000\n  - Diffuse: 0.8000\n") !=
        std::string::npos);
}

TEST_CASE("cli: pixelray and firsthit give the course's p1 answers, whatever the precision") {
  const rt::test::TempDir dir;
  const std::string scene = dir.write("s.pov", kScene);
  const std::string flag = GENERATE("--precision=auto", "--precision=float", "--precision=double",
                                    "--sphere=textbook", "--sphere=robust");
  CAPTURE(flag);
  CHECK(run({"pixelray", scene, "640", "480", "170", "120", flag}).out ==
        "Pixel: [170, 120] Ray: {0.0000 0.0000 14.0000} -> {-0.2893 -0.2313 -0.9289}\n");
  CHECK(run({"firsthit", scene, "640", "480", "320", "240", flag}).out ==
        "Pixel: [320, 240] Ray: {0.0000 0.0000 14.0000} -> {0.0010 0.0010 -1.0000}\n"
        "T = 12.0001\nObject Type: Sphere\nColor: 1.0000 0.0000 1.0000\n");
  CHECK(run({"firsthit", scene, "640", "480", "320", "160", flag}).out ==
        "Pixel: [320, 160] Ray: {0.0000 0.0000 14.0000} -> {0.0010 -0.1634 -0.9866}\n"
        "T = 24.4800\nObject Type: Plane\nColor: 0.2000 0.2000 0.8000\n");
  CHECK(run({"firsthit", scene, "640", "480", "400", "240", flag}).out ==
        "Pixel: [400, 240] Ray: {0.0000 0.0000 14.0000} -> {0.1654 0.0010 -0.9862}\nNo Hit\n");
}

TEST_CASE("cli: --stats reports render's steps on the error stream, and only for render") {
  const rt::test::TempDir dir;
  // A .cli file names its images, so nothing is written outside the test's directory.
  const std::string scene = dir.write("s.cli", "fov 60\nwrite " + dir.file("a.png") + "\n"
                                      "surface 1 1 1  0 0 0  0 0 0  1 0\nsphere 0 0 -3 1\n"
                                      "write " + dir.file("b.png") + "\n");
  const Run r = run({"render", scene, "8", "6", "-ss=2", "--threads", "1", "--stats"});
  CHECK(r.status == 0);
  CHECK(r.out.empty());
  // The times vary; the line's shape does not: one line for the file, however many images it writes.
  const std::string ms = "[0-9]+\\.[0-9] ms";
  CHECK_THAT(r.err, Catch::Matches("raytrace: load " + ms + ", build " + ms + ", trace " + ms + ", png " + ms +
                                   ", total " + ms + " \\(8x6, 4 eye rays per pixel, 1 thread\\)\n"
                                   "raytrace: rays 384 eye, 0 gather, [0-9]+ shadow, 0 secondary; [0-9]+\\.[0-9]{2} M "
                                   "rays/s in trace\n"));
  CHECK(dir.names() == std::vector<std::string>{"a.png", "b.png", "s.cli"});
  CHECK(run({"render", scene, "8", "6", "--threads", "1"}).err.empty());
  CHECK(errorOf({"sceneinfo", scene, "--stats"}) == "--stats is for the render command only");
  CHECK(errorOf({"pixelcolor", scene, "8", "6", "1", "1", "--stats"}) == "--stats is for the render command only");
}
