// The command line through runCommand with string streams: usage, every argument error with its whole
// message, and the Program 1 commands on a scene written by the test.
#include <catch2/catch.hpp>

#include <sstream>

#include "raytrace/app/arguments.hpp"
#include "raytrace/app/commands.hpp"
#include "raytrace/app/stats_report.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"
#include "command_error.hpp"
#include "temp_dir.hpp"

using rt::test::errorOf;

namespace {

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

// What pixelcolor prints of the centre of a 9×9 picture of `scene` with `hole` replaced by `fill`.
std::string centreColour(const rt::test::TempDir& dir, std::string scene, const std::string& hole,
                         const std::string& fill) {
  scene.replace(scene.find(hole), hole.size(), fill);
  const Run r = run({"pixelcolor", dir.write("centre.pov", scene), "9", "9", "4", "4"});
  REQUIRE(r.status == 0);
  return r.out.substr(r.out.find("Color: "));
}

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
  CHECK(errorOf({}) == "no command given (see raytrace --help)");
  CHECK(errorOf({"render2", "a.pov"}) == "unknown command 'render2': did you mean 'render'? (see raytrace --help)");
  CHECK(errorOf({"frobnicate", "a.pov"}) == "unknown command 'frobnicate' (see raytrace --help)");
  CHECK(errorOf({"help", "frobnicate"}) == "unknown command 'frobnicate' (see raytrace --help)");
  CHECK(errorOf({"sceneinfo", "a.pov", "--fast"}) == "unknown option '--fast' (see raytrace --help)");
  CHECK(errorOf({"sceneinfo", "a.pov", "--precision=quad"}) == "--precision must be float, double, course or auto, found 'quad'");
  CHECK(errorOf({"sceneinfo", "a.pov", "--sphere=fast"}) == "--sphere must be textbook, robust or auto, found 'fast'");
}

TEST_CASE("cli: an option a typo away from a known one is named") {
  CHECK(errorOf({"render", "a.pov", "--thread", "2"}) ==
        "unknown option '--thread': did you mean '--threads'? (see raytrace --help)");
  CHECK(errorOf({"render", "a.pov", "--dpeth=3"}) ==
        "unknown option '--dpeth=3': did you mean '--depth'? (see raytrace --help)");
  CHECK(errorOf({"render", "a.pov", "--ouptut", "a.png"}) ==
        "unknown option '--ouptut': did you mean '--output'? (see raytrace --help)");
  // A known option in the wrong form is unknown as written, with nothing to suggest.
  CHECK(errorOf({"render", "a.pov", "--depth"}) == "unknown option '--depth' (see raytrace --help)");
  CHECK(errorOf({"render", "a.pov", "-gi=1"}) == "unknown option '-gi=1' (see raytrace --help)");
}

TEST_CASE("cli: the help lists every option of the table, each once, with its spelling") {
  const std::string u = rt::usage();
  for (const rt::Option& o : rt::optionTable()) {
    // A label too long for the help's column has a line of its own.
    const std::string label = rt::optionLabel(o);
    const std::string line = "\n  " + label + (label.size() <= 30 ? " " : "\n");
    CHECK(u.find(line) != std::string::npos);
    CHECK(u.find(line) == u.rfind(line));
  }
  CHECK(rt::optionLabel(rt::optionTable().front()) == "--precision=float|double|course|auto");
  CHECK(u.find("  --stats[=text|json]             after render,") != std::string::npos);
  CHECK(u.find("  -o, --output FILE               the image file") != std::string::npos);
}

TEST_CASE("cli: help for one command, help itself and merge included") {
  const Run help = run({"help", "help"});
  CHECK(help.status == 0);
  CHECK(help.out == "usage: raytrace help <command>\nthe usage, summary and options of one command\n");
  CHECK(run({"help", "merge"}).out ==
        "usage: raytrace merge -o <image> <tile.exr>... [--threads N] [--for <scene> <width> <height> [options]]\n"
        "the tiles of one render (--tile, --region) joined into its image, exactly as one machine renders it\n"
        "options:\n"
        "  -o, --output FILE               the image (.png, .hdr or .exr; an .exr keeps the tiles' attributes)\n"
        "  --threads N                     convert on N threads (default: every core)\n"
        "  --for <scene> <width> <height> [render options]\n"
        "                                  last: every tile must be of this render (the scene's contents,\n"
        "                                  size, options and program version), or merge writes nothing\n"
        "  --for +I<scene> [POV-Ray options]\n"
        "                                  the same in POV-Ray's words, of one frame (+SF = +EF): its clock,\n"
        "                                  and without -o, the frame's numbered image name\n"
        "  --manifest FILE                 list in FILE the scene and the files it read (with --for), the\n"
        "                                  tiles and the image, one a line\n");
  CHECK(run({"merge", "--help"}).out == run({"help", "merge"}).out);
  const std::string sceneinfo = run({"help", "sceneinfo"}).out;
  CHECK(sceneinfo.rfind("usage: raytrace sceneinfo <scene> [options]\nthe camera, lights and objects as parsed\n"
                        "options:\n", 0) == 0);
  CHECK(sceneinfo.find("image options") == std::string::npos);
  CHECK(run({"help", "render"}).out.find("image options (raycast, render):\n  -o, --output FILE") != std::string::npos);
  CHECK(errorOf({"help"}) == "help takes one command, as in: raytrace help render");
  CHECK(errorOf({"hepl", "render"}) == "unknown command 'hepl': did you mean 'help'? (see raytrace --help)");
}

TEST_CASE("cli: the -gi flags and their bad values") {
  CHECK(errorOf({"render", "a.pov", "-gi_samples=64,x"}) == "-gi_samples must be a whole number, found 'x'");
  CHECK(errorOf({"render", "a.pov", "-gi_samples=64,"}) == "-gi_samples must be a whole number, found ''");
  CHECK(errorOf({"render", "a.pov", "-gi_samples=0"}) == "-gi_samples must be between 1 and 65536, found 0");
  CHECK(errorOf({"render", "a.pov", "-gi_bounces=17"}) == "-gi_bounces must be between 0 and 16, found 17");
  CHECK(errorOf({"render", "a.pov", "--seed"}) == "--seed needs a number");
  CHECK(errorOf({"render", "a.pov", "--seed=-1"}) == "--seed must be between 0 and 2147483647, found -1");
  CHECK(errorOf({"render", "a.pov", "--gi-cache=0"}) ==
        "--gi-cache must be a number above 0 and at most 1, found '0'");
  CHECK(errorOf({"render", "a.pov", "--gi-cache=0.1x"}) ==
        "--gi-cache must be a number above 0 and at most 1, found '0.1x'");
  CHECK(errorOf({"render", "a.pov", "--gi-cache=1.5"}) ==
        "--gi-cache must be a number above 0 and at most 1, found '1.5'");
  // Issue 35: a value of 5000 characters was echoed whole; it is quoted and cut as every other value.
  CHECK(errorOf({"render", "a.pov", "--gi-cache=" + std::string(5000, '7') + "\x1b[2J"}) ==
        "--gi-cache must be a number above 0 and at most 1, found '" + std::string(60, '7') + "...'");
  CHECK(errorOf({"render", "a.pov", "--gi-cache=0.1\x1b[2J"}) ==
        "--gi-cache must be a number above 0 and at most 1, found '0.1\\x1B[2J'");
  const rt::RenderOptions o = rt::parseFlag("-gi_bounces=3", rt::parseFlag("-gi_samples=32,8", rt::parseFlag("-gi", {})));
  CHECK(o.gi.enabled);
  CHECK(o.gi.samples == std::vector<int>{32, 8});
  CHECK(o.gi.bounceCount() == 3);
  CHECK(o.gi.samplesAt(2) == 8);
}

TEST_CASE("cli: wrong argument counts") {
  CHECK(errorOf({"sceneinfo"}) == "sceneinfo takes 1 arguments, found 0 (usage: raytrace sceneinfo <scene>)");
  CHECK(errorOf({"sceneinfo", "a.pov", "640"}) ==
        "sceneinfo takes 1 arguments, found 2 (usage: raytrace sceneinfo <scene>)");
  CHECK(errorOf({"raycast", "a.pov", "640"}) ==
        "raycast takes 3 arguments, found 2 (usage: raytrace raycast <scene> <width> <height>)");
  CHECK(errorOf({"pixelray", "a.pov", "640", "480"}) ==
        "pixelray takes 5 arguments, found 3 (usage: raytrace pixelray <scene> <width> <height> <x> <y>)");
  CHECK(errorOf({"firsthit", "a.pov", "640", "480", "1", "2", "3"}) ==
        "firsthit takes 5 arguments, found 6 (usage: raytrace firsthit <scene> <width> <height> <x> <y>)");
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
  // A .cli file names its images, so nothing is written outside the test's directory: by absolute paths, which
  // the user must allow.
  const std::string scene = dir.write("s.cli", "fov 60\nwrite " + dir.file("a.png") + "\n"
                                      "surface 1 1 1  0 0 0  0 0 0  1 0\nsphere 0 0 -3 1\n"
                                      "write " + dir.file("b.png") + "\n");
  const Run r = run({"render", scene, "8", "6", "-ss=2", "--threads", "1", "--stats", "--allow-write-anywhere"});
  CHECK(r.status == 0);
  CHECK(r.out.empty());
  // The times vary; the line's shape does not: one line for the file, however many images it writes.
  const std::string ms = "[0-9]+\\.[0-9] ms";
  CHECK_THAT(r.err, Catch::Matches("raytrace: load " + ms + ", build " + ms + ", trace " + ms + ", write " + ms +
                                   ", total " + ms + " \\(8x6, 4 eye rays per pixel, 1 thread\\)\n"
                                   "raytrace: rays 384 eye, 0 gather, [0-9]+ shadow, 0 secondary; [0-9]+\\.[0-9]{2} M "
                                   "rays/s in trace\n"));
  CHECK(dir.names() == std::vector<std::string>{"a.png", "b.png", "s.cli"});
  CHECK(run({"render", scene, "8", "6", "--threads", "1", "--allow-write-anywhere"}).err.empty());
  // --gi-cache adds the cache's line: records made, lookups, and points gathered without a record (none).
  const Run cached = run({"render", scene, "8", "6", "-gi", "-gi_samples=4,2", "--gi-cache=0.3", "--threads", "1",
                          "--stats", "--allow-write-anywhere"});
  CHECK_THAT(cached.err, Catch::Contains(" M rays/s in trace\n"));
  CHECK_THAT(cached.err, Catch::Matches("(.*\n){2}raytrace: irradiance cache [1-9][0-9]* records, [1-9][0-9]* lookups, "
                                        "0 gathered uncached\n"));
  CHECK(errorOf({"sceneinfo", scene, "--stats"}) == "--stats is for the render command only");
  CHECK(errorOf({"pixelcolor", scene, "8", "6", "1", "1", "--stats"}) == "--stats is for the render command only");
  CHECK(errorOf({"sceneinfo", scene, "--stats=json"}) == "--stats is for the render command only");
  CHECK(errorOf({"render", scene, "--stats=xml"}) == "--stats must be text or json, found 'xml'");
  CHECK(errorOf({"raycast", scene, "8", "6", "--display"}) == "--display is for the render command only");
  CHECK(errorOf({"raycast", scene, "8", "6", "--preview", "p.png"}) == "--preview is for the render command only");
}

TEST_CASE("cli: --stats=json gives the text's figures as one JSON object") {
  const rt::test::TempDir dir;
  std::string plain = kScene;
  plain.erase(plain.find(" metallic 1"), 11);  // no warning before the figures
  const std::string scene = dir.write("s.pov", plain);
  const std::string out = dir.file("a.png");
  const Run text = run({"render", scene, "8", "6", "-ss=2", "--threads", "1", "--stats", "-o", out});
  const Run json = run({"render", scene, "8", "6", "-ss=2", "--threads", "1", "--stats=json", "-o", out});
  CHECK(json.status == 0);
  // The rays and the settings are the same in both runs; the times and the memory vary.
  const std::string rays = "raytrace: rays 192 eye, 0 gather, 98 shadow, 0 secondary; ";
  CHECK(text.err.find(rays) != std::string::npos);
  CHECK(text.err.find("(8x6, 4 eye rays per pixel, 1 thread)\n") != std::string::npos);
  const std::string ms = "[0-9]+\\.[0-9]";
  CHECK_THAT(json.err, Catch::Matches("\\{\"width\": 8, \"height\": 6, \"eye_rays_per_pixel\": 4, \"threads\": 1, "
                                      "\"milliseconds\": \\{\"load\": " + ms + ", \"build\": " + ms + ", \"trace\": " +
                                      ms + ", \"write\": " + ms + ", \"total\": " + ms + "\\}, \"rays\": \\{\"eye\": 192, "
                                      "\"gather\": 0, \"shadow\": 98, \"secondary\": 0, \"total\": 290\\}, "
                                      "\"million_rays_per_second\": [0-9]+\\.[0-9]{2}, \"peak_memory_bytes\": [1-9][0-9]*\\}\n"));
}

TEST_CASE("cli: the stats' text and JSON of the same figures") {
  rt::RenderStats s;
  s.width = 640;
  s.height = 480;
  s.eyeRays = 9;
  s.threads = 2;
  s.load = 0.0012;
  s.build = 0.25;
  s.trace = 2;
  s.write = 0.04;
  s.rays.eye = 2764800;
  s.rays.shadow = 1000000;
  s.rays.secondary = 235200;
  s.peakMemory = 1048576;
  CHECK(rt::statsText(s) == "raytrace: load 1.2 ms, build 250.0 ms, trace 2000.0 ms, write 40.0 ms, total 2291.2 ms "
                            "(640x480, 9 eye rays per pixel, 2 threads)\n"
                            "raytrace: rays 2764800 eye, 0 gather, 1000000 shadow, 235200 secondary; 2.00 M rays/s "
                            "in trace\n");
  CHECK(rt::statsJson(s) == "{\"width\": 640, \"height\": 480, \"eye_rays_per_pixel\": 9, \"threads\": 2, "
                            "\"milliseconds\": {\"load\": 1.2, \"build\": 250.0, \"trace\": 2000.0, \"write\": 40.0, "
                            "\"total\": 2291.2}, \"rays\": {\"eye\": 2764800, \"gather\": 0, \"shadow\": 1000000, "
                            "\"secondary\": 235200, \"total\": 4000000}, \"million_rays_per_second\": 2.00, "
                            "\"peak_memory_bytes\": 1048576}\n");
  s.cache = true;
  s.rays.cacheRecords = 3;
  s.rays.cacheLookups = 40;
  CHECK(rt::statsText(s).substr(rt::statsText(s).rfind("raytrace:")) ==
        "raytrace: irradiance cache 3 records, 40 lookups, 0 gathered uncached\n");
  CHECK(rt::statsJson(s).find(", \"irradiance_cache\": {\"records\": 3, \"lookups\": 40, \"gathered_uncached\": 0}, "
                              "\"peak_memory_bytes\"") != std::string::npos);
  // Adaptive anti-aliasing and focal blur give the mean.
  s.eyeRays = 2.4375;
  CHECK(rt::statsText(s).find("(640x480, 2.44 eye rays per pixel, 2 threads)") != std::string::npos);
  CHECK(rt::statsJson(s).find("\"eye_rays_per_pixel\": 2.44,") != std::string::npos);
}

TEST_CASE("cli: 30,000 identical warnings are one line with their count") {
  const rt::test::TempDir dir;
  std::string text = "camera { location <0,0,5> look_at <0,0,0> }\n";
  for (int i = 0; i < 30000; ++i) text += "sphere { <0,0,0>, 1 pigment { rgb <1,0,0,0.5> } }\n";
  const std::string scene = dir.write("w.pov", text);
  const Run r = run({"sceneinfo", scene, "--threads", "2"});
  CHECK(r.status == 0);
  CHECK(r.err == scene + ":2:35: warning: 'rgb' with 4 values; the fourth is read as the filter "
                         "(and 29,999 more like it)\n");
}

TEST_CASE("cli: a UTF-8 byte-order mark is skipped in both languages") {
  const rt::test::TempDir dir;
  const std::string bom = "\xEF\xBB\xBF";
  const std::string pov = dir.write("b.pov", bom + kScene);
  CHECK(run({"sceneinfo", pov}).out == run({"sceneinfo", dir.write("plain.pov", kScene)}).out);
  const std::string cli = dir.write("b.cli", bom + "fov 60\nsurface 0 0 0 1 1 1 0 0 0 1 0\nsphere 0 0 -4 1\n");
  const Run r = run({"sceneinfo", cli});
  CHECK(r.status == 0);
  CHECK(r.out.find("1 object(s)") != std::string::npos);
  // Only at the very start: elsewhere it is bytes no scene may hold.
  const std::string late = dir.write("late.pov", "\n" + bom + kScene);
  CHECK(errorOf({"sceneinfo", late}) == late + ":2:1: error: unexpected byte 0xEF (is this a text scene file?)");
}

TEST_CASE("cli: a 10 MB word and a 100 KB argument are quoted cut, on one line") {
  const rt::test::TempDir dir;
  const std::string word(10'000'000, 'w');
  const std::string pov = dir.write("w.pov", "camera { location <0,0,5> look_at <0,0,0> }\n" + word + "\n");
  CHECK(errorOf({"sceneinfo", pov}) ==
        pov + ":2:1: error: unknown keyword '" + std::string(60, 'w') + "...'");
  const std::string cli = dir.write("w.cli", "fov 60\n" + word + "\n");
  CHECK(errorOf({"sceneinfo", cli}) == cli + ":2:1: error: unknown command '" + std::string(60, 'w') +
                                           "...' (the commands are fov, background, light, surface, sphere, "
                                           "cylinder, write)");
  CHECK(errorOf({"raycast", pov, std::string(100'000, '9'), "4"}) ==
        "width must be between 1 and 32768, found " + std::string(60, '9') + "...");
}

TEST_CASE("cli: a .cli write outside the current folder needs --allow-write-anywhere") {
  const rt::test::TempDir dir;
  const std::string target = dir.file("out.png");
  const std::string scene = dir.write("s.cli", "fov 60\nwrite " + target + "\n");
  CHECK(errorOf({"render", scene, "4", "4"}) ==
        scene + ":2:1: error: 'write' may only name a file in the folder the scene is rendered into and below, "
                "found " + rt::quote(target) + " (--allow-write-anywhere allows it)");
  CHECK(dir.names() == std::vector<std::string>{"s.cli"});
  CHECK(run({"render", scene, "4", "4", "--allow-write-anywhere"}).status == 0);
  CHECK(dir.names() == std::vector<std::string>{"out.png", "s.cli"});
}

TEST_CASE("cli: a POV-Ray scene's diffuse light takes brilliance as the power of n·l, written as sRGB") {
  const rt::test::TempDir dir;
  // The plane y = 0 seen from straight above, lit from 60° off its normal: n·l = ½.
  const std::string scene = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                            "camera { location <0, 5, 0> look_at 0 }\n"
                            "light_source { <1000 * sqrt(3), 1000, 0> rgb 1 }\n"
                            "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 BRILLIANCE } }\n";
  const auto colour = [&](const std::string& brilliance) { return centreColour(dir, scene, "BRILLIANCE", brilliance); };
  CHECK(colour("") == "Color: (188, 188, 188)\n");             // sRGB(0.5)
  CHECK(colour("brilliance 2") == "Color: (137, 137, 137)\n");  // sRGB(0.25)
}

TEST_CASE("cli: a POV-Ray scene's shadows pass transparent surfaces, each tinting the light as POV-Ray does") {
  const rt::test::TempDir dir;
  // A thin box between the light and the point seen; the eye ray passes beside it. POV-Ray gave the colours.
  const std::string scene = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                            "camera { location <0, 5, -5> look_at 0 }\nlight_source { <0, 100, 0> rgb 1 }\n"
                            "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
                            "box { <-1, 0.99, -0.5>, <1, 1.01, 0.5> pigment { PIGMENT } finish { ambient 0 diffuse 0 } }\n";
  const auto colour = [&](const std::string& pigment) { return centreColour(dir, scene, "PIGMENT", pigment); };
  CHECK(colour("rgbf <1, 0, 0, 1>") == "Color: (255, 0, 0)\n");
  CHECK(colour("rgbt <1, 0, 0, 0.5>") == "Color: (137, 137, 137)\n");
  CHECK(colour("rgbft <1, 0, 0, 0.5, 0.25>") == "Color: (198, 71, 71)\n");
  CHECK(colour("rgb <1, 0, 0>") == "Color: (0, 0, 0)\n");
}

TEST_CASE("cli: a POV-Ray interior's caustics brighten the shadow by how the surface faces the light") {
  const rt::test::TempDir dir;
  // A disc of filter 0.5, tilted by the angle A, between a parallel light straight above and the plane seen from
  // above: 1 + cos(A)^(45·caustics) of the shadow's light. POV-Ray gave the colours.
  const std::string scene = "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
                            "camera { orthographic location <0, 10, 0> look_at 0 right x * 2 up z * 2 }\n"
                            "light_source { <0, 1000, 0> rgb 1 parallel point_at 0 }\n"
                            "plane { y, 0 pigment { rgb 0.5 } finish { ambient 0 diffuse 1 } }\n"
                            "disc { <0, 1, 0>, y, 100 INTERIOR pigment { rgbf <1, 1, 1, 0.5> } finish { ambient 0 "
                            "diffuse 0 } no_image }\n";
  const auto colour = [&](const std::string& interior) { return centreColour(dir, scene, "INTERIOR", interior); };
  CHECK(colour("") == "Color: (137, 137, 137)\n");  // sRGB(0.25)
  CHECK(colour("rotate x * 5 interior { caustics 1 }") == "Color: (181, 181, 181)\n");
  CHECK(colour("rotate x * 20 interior { caustics 0.25 }") == "Color: (165, 165, 165)\n");
  CHECK(colour("interior { caustics 1 }") == "Color: (188, 188, 188)\n");  // facing the light: twice the light
}
