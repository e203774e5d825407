// The image commands' output: -o and its formats, the errors of bad -o values (whole messages, found before
// the scene is read), tiles merged into exactly the one-machine image, merge's errors, help and --version.
#include <catch2/catch.hpp>

#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

#include "raytrace/app/commands.hpp"
#include "raytrace/image/exr_file.hpp"
#include "raytrace/util/error.hpp"
#include "command_error.hpp"
#include "temp_dir.hpp"

using rt::test::errorOf;

namespace {

std::string outputOf(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  REQUIRE(rt::runCommand(args, out, err) == 0);
  return out.str();
}

// What a command that succeeds says on stderr.
std::string messagesOf(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  REQUIRE(rt::runCommand(args, out, err) == 0);
  return err.str();
}

// A glossy sphere over a plane, with reflections: smooth and sharp pixels for the sub-samples to differ in.
const char* const kScene =
    "camera { location <0,1,6> up <0,1,0> right <1.33333,0,0> look_at <0,0,0> }\n"
    "light_source { <-10,10,10> color rgb <1.5,1.5,1.5> }\n"
    "sphere { <0,0,0>, 1.5 pigment { color rgb <1,0.3,0.2> } finish { ambient 0.2 diffuse 0.6 specular 0.6 "
    "roughness 0.05 reflection 0.3 } }\n"
    "plane { <0,1,0>, -1.5 pigment { color rgb <0.2,0.7,0.3> } finish { ambient 0.3 diffuse 0.8 reflection 0.2 } }\n";

}  // namespace

TEST_CASE("image commands: -o names the file and its format; an .exr converts to the very same PNG") {
  const rt::test::TempDir dir;
  const std::string scene = dir.write("s.pov", kScene);
  for (const std::string command : {"raycast", "render"}) {
    CAPTURE(command);
    const std::string png = dir.file(command + ".png"), exr = dir.file(command + ".exr");
    CHECK(outputOf({command, scene, "40", "30", "-o", png}).empty());
    CHECK(outputOf({command, scene, "40", "30", "--output", exr}).empty());
    CHECK(outputOf({command, scene, "40", "30", "--output=" + dir.file(command + ".hdr")}).empty());
    // The whole image is a tile of itself: merge converts its floats as the render converts them.
    CHECK(outputOf({"merge", "-o", dir.file(command + "-merged.png"), exr}).empty());
    CHECK(rt::test::readAll(dir.file(command + "-merged.png")) == rt::test::readAll(png));
    const rt::ExrImage image = rt::readExr(exr);
    CHECK(image.attributes.at("raytrace.command") == command);
    CHECK(image.attributes.at("raytrace.scene") == "s.pov");
    CHECK(image.attributes.at("raytrace.size") == "40x30");
    CHECK(image.attributes.at("raytrace.toByte") == "round");
    CHECK(image.attributes.at("raytrace.part") == "0,0,40,30");
  }
  CHECK(dir.names().size() == 9);
}

TEST_CASE("image commands: bad -o values are one whole message, before the scene is even read") {
  const rt::test::TempDir dir;
  const std::string file = dir.write("f", "x");
  // The scene does not exist: each error comes first.
  const std::string scene = dir.file("missing.pov");
  CHECK(errorOf({"render", scene, "-o", dir.file("a.jpg")}) ==
        "cannot write '" + dir.file("a.jpg") + "': unknown image format '.jpg' (name it .png, .hdr or .exr)");
  CHECK(errorOf({"raycast", scene, "4", "3", "-o", dir.file("image")}) ==
        "cannot write '" + dir.file("image") + "': no image format (name it .png, .hdr or .exr)");
  CHECK(errorOf({"render", scene, "-o", dir.file("no/a.png")}) ==
        "cannot write '" + dir.file("no/a.png") + "': No such file or directory");
  CHECK(errorOf({"render", scene, "-o", file + "/a.png"}) == "cannot write '" + file + "/a.png': Not a directory");
  CHECK(errorOf({"render", scene, "-o"}) == "-o needs a value");
  CHECK(errorOf({"render", scene, "--output="}) == "--output= needs a file name");
  CHECK(errorOf({"sceneinfo", scene, "-o", "a.png"}) == "-o is for the commands that write images (raycast, render)");
  // Issue 35: the value of --output= was echoed raw, terminal escapes and all.
  CHECK(errorOf({"sceneinfo", scene, "--output=\x1b[2J" + std::string(5000, 'a')}) ==
        "--output is for the commands that write images (raycast, render)");
  CHECK(errorOf({"render", scene, "--tile", "0/2"}) == "a tile is written as OpenEXR: name it with -o NAME.exr");
  CHECK(errorOf({"render", scene, "--tile", "0/2", "-o", "t.png"}) ==
        "cannot write 't.png': a tile is written as OpenEXR (name it .exr)");
  CHECK(errorOf({"render", scene, "--tile", "2/2", "-o", "t.exr"}) == "--tile's I must be between 0 and 1, found 2");
  CHECK(errorOf({"render", scene, "--tile", "0/301", "-o", "t.exr"}) == "--tile's N must be between 1 and 300, found 301");
  CHECK(errorOf({"render", scene, "--tile", "1", "-o", "t.exr"}) == "--tile must be I/N, as 0/4, found '1'");
  CHECK(errorOf({"render", scene, "--region", "0,0,10", "-o", "t.exr"}) ==
        "--region must be X0,Y0,X1,Y1, as 0,0,64,48, found '0,0,10'");
  CHECK(errorOf({"render", scene, "--region", "5,0,5,10", "-o", "t.exr"}) ==
        "--region's X1 must be between 6 and 300, found 5");
  CHECK(errorOf({"render", scene, "--region", "0,0,9,9", "--tile", "0/2", "-o", "t.exr"}) ==
        "--tile and --region both name the part to render: give one");
  CHECK(dir.names() == std::vector<std::string>{"f"});
}

TEST_CASE("image commands: -o and a .cli scene's own images") {
  const rt::test::TempDir dir;
  const std::string one = dir.write("one.cli", "fov 60\nsurface 1 1 1 0 0 0 0 0 0 1 0\nsphere 0 0 -3 1\nwrite a.png\n");
  const std::string two = dir.write("two.cli", "fov 60\nwrite a.png\nwrite b.png\n");
  REQUIRE(outputOf({"render", one, "8", "6", "-o", dir.path()}).empty());  // a folder: the writes go in it
  CHECK(dir.names() == std::vector<std::string>{"a.png", "one.cli", "two.cli"});
  REQUIRE(outputOf({"render", one, "8", "6", "-o", dir.file("c.exr")}).empty());  // one image: -o replaces it
  CHECK(outputOf({"render", two, "8", "6", "-o", dir.path()}).empty());
  CHECK(dir.names() == std::vector<std::string>{"a.png", "b.png", "c.exr", "one.cli", "two.cli"});
  CHECK(errorOf({"render", two, "8", "6", "-o", dir.file("c.png")}) ==
        "'" + two + "' writes 2 images: -o must name a folder to write them into");
  const std::string pov = dir.write("s.pov", kScene);
  CHECK(errorOf({"render", pov, "8", "6", "-o", dir.path()}) ==
        "-o '" + dir.path() + "' is a folder, but '" + pov + "' names no images of its own: give -o the image's file name");
}

TEST_CASE("image commands: a .cli scene's images are tiled into -o's folder, each merged into its one-machine bytes") {
  const rt::test::TempDir dir;
  const std::string two = dir.write("two.cli", "fov 60\nlight 1 1 1 1 1 1\nsurface .2 .2 .2 1 1 1 0 0 0 1 0\n"
                                               "sphere 0 0 -4 1\nwrite a.png\nsphere 1 0 -4 0.5\nwrite b.png\n");
  for (const std::string part : {"0", "1"}) {
    REQUIRE(mkdir(dir.file("t" + part).c_str(), 0755) == 0);
    REQUIRE(outputOf({"render", two, "16", "12", "--tile", part + "/2", "-o", dir.file("t" + part)}).empty());
  }
  REQUIRE(mkdir(dir.file("whole").c_str(), 0755) == 0);
  REQUIRE(outputOf({"render", two, "16", "12", "-o", dir.file("whole")}).empty());
  for (const std::string image : {"a", "b"}) {
    const std::string merged = dir.file(image + ".png");
    REQUIRE(outputOf({"merge", "-o", merged, dir.file("t0/" + image + ".exr"), dir.file("t1/" + image + ".exr"),
                      "--for", two, "16", "12"}).empty());
    CHECK(rt::test::readAll(merged) == rt::test::readAll(dir.file("whole/" + image + ".png")));
  }
  CHECK(errorOf({"merge", "-o", dir.file("x.png"), dir.file("t0/a.exr"), dir.file("t1/b.exr")}) ==
        "'" + dir.file("t1/b.exr") + "' is a tile of another render than '" + dir.file("t0/a.exr") +
            "': its raytrace.image is 'b.png', not 'a.png'");
  CHECK(messagesOf({"render", two, "16", "12", "--tile", "0/2", "-o", dir.file("t0"), "--resume"}) ==
        "raytrace: '" + dir.file("t0/a.exr") + "' is already this tile: kept\nraytrace: '" + dir.file("t0/b.exr") +
            "' is already this tile: kept\n");
  const std::string same = dir.write("same.cli", "fov 60\nwrite c.png\nwrite c.png\n");
  CHECK(errorOf({"render", same, "16", "12", "--tile", "0/2", "-o", dir.file("t0")}) ==
        same + ":3:1: error: this image's tile would be '" + dir.file("t0/c.exr") + "' too");
}

TEST_CASE("image commands: -o's folder keeps a .cli scene's writes in it, and a failed write does not stop the others") {
  const rt::test::TempDir dir, outDir;
  const std::string out = outDir.path();
  const std::string up = dir.write("up.cli", "fov 60\nwrite ../escaped.png\n");
  CHECK(errorOf({"render", up, "8", "6", "-o", out}) ==
        up + ":2:1: error: 'write' may only name a file in the folder the scene is rendered into and below, "
             "found '../escaped.png' (--allow-write-anywhere allows it)");
  CHECK(outDir.names().empty());
  CHECK(dir.names() == std::vector<std::string>{"up.cli"});
  const std::string three = dir.write("three.cli", "fov 60\nwrite first.png\nwrite no/second.png\nwrite third.png\n");
  std::ostringstream stdoutText, errors;
  CHECK(rt::runCommand({"render", three, "8", "6", "-o", out}, stdoutText, errors) == 1);
  CHECK(errors.str() == three + ":3:1: error: cannot write '" + out + "/no/second.png': No such file or directory\n");
  CHECK(outDir.names() == std::vector<std::string>{"first.png", "third.png"});
}

TEST_CASE("image commands: a .cli write through a symbolic link out of -o's folder is refused, one inside is not") {
  const rt::test::TempDir dir, outDir, elsewhere;
  const std::string out = outDir.path();
  REQUIRE(symlink(elsewhere.path().c_str(), outDir.file("away").c_str()) == 0);
  REQUIRE(mkdir(outDir.file("real").c_str(), 0755) == 0);
  REQUIRE(symlink("real", outDir.file("near").c_str()) == 0);
  const std::string away = dir.write("away.cli", "fov 60\nwrite away/x.png\n");
  CHECK(errorOf({"render", away, "8", "6", "-o", out}) ==
        away + ":2:1: error: 'write' names 'away/x.png', but a folder on its way is a symbolic link out of the "
               "folder the scene is rendered into (--allow-write-anywhere allows it)");
  CHECK(elsewhere.names().empty());
  CHECK(outputOf({"render", away, "8", "6", "-o", out, "--allow-write-anywhere"}).empty());
  CHECK(elsewhere.names() == std::vector<std::string>{"x.png"});
  const std::string near = dir.write("near.cli", "fov 60\nwrite near/y.png\n");
  CHECK(outputOf({"render", near, "8", "6", "-o", out}).empty());
  CHECK(outDir.names() == std::vector<std::string>{"away", "near", "real"});
  CHECK(rt::test::readAll(outDir.file("real/y.png")).substr(1, 3) == "PNG");
}

TEST_CASE("image commands: tiles of any count and thread count merge into the one-machine bytes, with -ss") {
  const rt::test::TempDir dir;
  const std::string scene = dir.write("s.pov", kScene);
  const std::string whole = dir.file("whole.png");
  REQUIRE(outputOf({"render", scene, "64", "47", "-ss=2", "-o", whole}).empty());
  for (const int n : {1, 3, 7}) {
    CAPTURE(n);
    std::vector<std::string> merge{"merge", "-o", dir.file("merged.png")};
    for (int i = n - 1; i >= 0; --i) {  // in any order
      const std::string tile = dir.file("t" + std::to_string(i) + ".exr");
      REQUIRE(outputOf({"render", scene, "64", "47", "-ss=2", "--threads", std::to_string(1 + i % 3), "--tile",
                        std::to_string(i) + "/" + std::to_string(n), "-o", tile})
                  .empty());
      merge.push_back(tile);
    }
    REQUIRE(outputOf(merge).empty());
    CHECK(rt::test::readAll(dir.file("merged.png")) == rt::test::readAll(whole));
  }
  // Regions in a grid, not bands: the same.
  std::vector<std::string> merge{"merge", "-o", dir.file("grid.png")};
  for (const char* region : {"0,0,20,30", "20,0,64,30", "0,30,50,47", "50,30,64,47"}) {
    const std::string tile = dir.file(std::string("r") + region + ".exr");
    REQUIRE(outputOf({"render", scene, "64", "47", "-ss=2", "--region", region, "-o", tile}).empty());
    merge.push_back(tile);
  }
  REQUIRE(outputOf(merge).empty());
  CHECK(rt::test::readAll(dir.file("grid.png")) == rt::test::readAll(whole));
  // raycast's tiles too.
  REQUIRE(outputOf({"raycast", scene, "64", "47", "-o", dir.file("cast.png")}).empty());
  for (const char* part : {"0/2", "1/2"}) {
    REQUIRE(outputOf({"raycast", scene, "64", "47", "--tile", part, "-o", dir.file(std::string("c") + part[0] + ".exr")})
                .empty());
  }
  REQUIRE(outputOf({"merge", "-o", dir.file("cast-merged.png"), dir.file("c0.exr"), dir.file("c1.exr")}).empty());
  CHECK(rt::test::readAll(dir.file("cast-merged.png")) == rt::test::readAll(dir.file("cast.png")));
}

TEST_CASE("image commands: merge refuses tiles that do not make one picture, naming the file, writing nothing") {
  const rt::test::TempDir dir;
  const std::string scene = dir.write("s.pov", kScene);
  const auto tile = [&](const std::string& name, const std::string& part, std::vector<std::string> more = {}) {
    std::vector<std::string> args{"render", scene, "32", "24", "--tile", part, "-o", dir.file(name)};
    args.insert(args.end(), more.begin(), more.end());
    REQUIRE(outputOf(args).empty());
    return dir.file(name);
  };
  const std::string t0 = tile("t0.exr", "0/2"), t1 = tile("t1.exr", "1/2");
  const std::string ss = tile("ss.exr", "1/2", {"-ss=2"});
  const std::string third = tile("third.exr", "1/3");
  const std::string out = dir.file("out.png");
  CHECK(errorOf({"merge", "-o", out, t0}) ==
        "the tiles leave 384 pixels of the picture uncovered, the first at column 0, row 12");
  CHECK(errorOf({"merge", "-o", out, t0, t1, third}) == "'" + third + "' overlaps '" + t0 + "' at column 0, row 8");
  CHECK(errorOf({"merge", "-o", out, t0, ss}) ==
        "'" + ss + "' is a tile of another render than '" + t0 + "': its raytrace.options is '-ss=2', not ''");
  // -gi's settings are the render's too: another seed or sample list is another picture.
  const std::string gi0 = tile("gi0.exr", "0/2", {"-gi", "-gi_samples=2,1", "--seed", "3"});
  const std::string gi1 = tile("gi1.exr", "1/2", {"-gi", "-gi_samples=2,1", "--seed", "4", "--gi-cache=0.25"});
  CHECK(errorOf({"merge", "-o", out, gi0, gi1}) ==
        "'" + gi1 + "' is a tile of another render than '" + gi0 +
            "': its raytrace.options is '-gi -gi_samples=2,1 --seed=4 --gi-cache=0.25', "
            "not '-gi -gi_samples=2,1 --seed=3'");
  REQUIRE(outputOf({"render", scene, "32", "25", "--tile", "1/2", "-o", dir.file("tall.exr")}).empty());
  CHECK(errorOf({"merge", "-o", out, t0, dir.file("tall.exr")}) ==
        "'" + dir.file("tall.exr") + "' is a tile of another render than '" + t0 + "': its raytrace.size is '32x25', not '32x24'");
  // The same name, other contents.
  dir.write("s.pov", std::string(kScene) + "sphere { <2,0,0>, 0.5 pigment { color rgb <1,1,1> } }\n");
  const std::string edited = tile("edited.exr", "1/2");
  CHECK_THAT(errorOf({"merge", "-o", out, t0, edited}),
             Catch::Matches("'" + edited + "' is a tile of another render than '" + t0 +
                            "': its raytrace.sceneHash is '[0-9a-f]{16}', not '[0-9a-f]{16}'"));
  rt::writeExr(rt::ExrImage{32, 24, rt::Region{0, 12, 32, 24}, rt::Image(32, 12), {}}, dir.file("plain.exr"));
  CHECK(errorOf({"merge", "-o", out, t0, dir.file("plain.exr")}) ==
        "'" + dir.file("plain.exr") + "' is not a raytrace tile: it has no raytrace.command attribute");
  const std::string text = dir.write("text.exr", "not an image");
  CHECK_THAT(errorOf({"merge", "-o", out, t0, text}), Catch::StartsWith("cannot read '" + text + "': "));
  CHECK(errorOf({"merge", t0, t1}) == "merge needs -o OUTPUT, the image to write");
  CHECK(errorOf({"merge", "-o", out}) == "merge needs the tiles to join");
  CHECK(errorOf({"merge", "-o", dir.file("out.gif"), t0, t1}) ==
        "cannot write '" + dir.file("out.gif") + "': unknown image format '.gif' (name it .png, .hdr or .exr)");
  CHECK(errorOf({"merge", "-o", out, "--fast", t0}) == "unknown option '--fast' for merge (see raytrace help merge)");
  CHECK(dir.names() == std::vector<std::string>{"edited.exr", "gi0.exr", "gi1.exr", "plain.exr", "s.pov", "ss.exr",
                                                "t0.exr", "t1.exr", "tall.exr", "text.exr", "third.exr"});
}

TEST_CASE("image commands: --resume keeps a tile of this very render, renders a missing, unreadable or stale one") {
  // Issue 35: resuming used to keep any tile that was there, of whatever render.
  const rt::test::TempDir dir;
  const std::string scene = dir.write("s.pov", kScene);
  const std::string tile = dir.file("t.exr"), q = "raytrace: '" + tile + "' is ";
  const auto resumed = [&](std::vector<std::string> more) {
    std::vector<std::string> args{"render", scene, "32", "24", "--tile", "1/2", "-o", tile, "--resume"};
    args.insert(args.end(), more.begin(), more.end());
    return messagesOf(args);
  };
  CHECK(resumed({}) == q + "missing: rendering it\n");
  const std::string first = rt::test::readAll(tile);
  CHECK(resumed({}) == q + "already this tile: kept\n");
  CHECK(rt::test::readAll(tile) == first);
  CHECK(resumed({"-ss=2"}) == q + "stale (its raytrace.options is '', not '-ss=2'): rendering it\n");
  CHECK(resumed({"-ss=2"}) == q + "already this tile: kept\n");
  dir.write("s.pov", std::string(kScene) + "// edited\n");
  CHECK_THAT(resumed({"-ss=2"}), Catch::Matches("raytrace: '.*t\\.exr' is stale \\(its raytrace.sceneHash is "
                                                "'[0-9a-f]{16}', not '[0-9a-f]{16}'\\): rendering it\n"));
  CHECK(messagesOf({"render", scene, "32", "24", "-ss=2", "--tile", "0/2", "-o", tile, "--resume"}) ==
        q + "stale (its raytrace.part is '1/2', not '0/2'): rendering it\n");
  CHECK(messagesOf({"render", scene, "32", "24", "-ss=2", "--region", "0,0,32,12", "-o", tile, "--resume"}) ==
        q + "stale (its raytrace.part is '0/2', not '0,0,32,12'): rendering it\n");
  dir.write("t.exr", first.substr(0, 100));
  CHECK_THAT(resumed({}), Catch::StartsWith(q + "unreadable (cannot read '" + tile + "': ") &&
                              Catch::EndsWith("): rendering it\n"));
  CHECK(resumed({}) == q + "already this tile: kept\n");
  CHECK(errorOf({"render", scene, "32", "24", "-o", dir.file("w.exr"), "--resume"}) ==
        "--resume is for tiles: give --tile or --region");
}

TEST_CASE("image commands: merge --for refuses a tile of another request; an .exr keeps the attributes") {
  const rt::test::TempDir dir;
  const std::string scene = dir.write("s.pov", kScene);
  const std::string t0 = dir.file("t0.exr"), t1 = dir.file("t1.exr"), out = dir.file("out.png");
  REQUIRE(outputOf({"render", scene, "32", "24", "--tile", "0/2", "-o", t0}).empty());
  REQUIRE(outputOf({"render", scene, "32", "24", "--tile", "1/2", "-o", t1}).empty());
  CHECK(outputOf({"merge", "-o", out, t0, t1, "--for", scene, "32", "24", "--threads", "2"}).empty());
  CHECK(errorOf({"merge", "-o", out, t0, t1, "--for", scene, "40", "30"}) ==
        "'" + t0 + "' is not a tile of the render asked for: its raytrace.size is '32x24', not '40x30'");
  CHECK(errorOf({"merge", "-o", out, t0, t1, "--for", scene, "32", "24", "-fresnel"}) ==
        "'" + t0 + "' is not a tile of the render asked for: its raytrace.options is '', not '-fresnel'");
  CHECK(errorOf({"merge", "-o", out, t0, t1, "--for", scene, "32"}) ==
        "merge's --for takes the scene, width and height, then render options (see raytrace help merge)");
  CHECK(errorOf({"merge", "-o", out, t0, t1, "--for", scene, "32", "24", "--tile", "0/2"}) ==
        "merge's --for names the whole render: its scene, size and render options only");
  // An attribute's name from a file is shown as any other text from input: terminal escapes stay out.
  rt::ExrImage odd = rt::readExr(t1);
  odd.attributes["\x1b[2J"] = "x";
  rt::writeExr(odd, dir.file("odd.exr"));
  CHECK(errorOf({"merge", "-o", out, t0, dir.file("odd.exr")}) == "'" + dir.file("odd.exr") +
                                                                   "' is a tile of another render than '" + t0 +
                                                                   "': its \\x1B[2J is 'x', not none");
  // Merged to OpenEXR: the one-machine file, byte for byte, so a tile of its render in turn.
  const std::string merged = dir.file("merged.exr"), one = dir.file("one.exr");
  REQUIRE(outputOf({"merge", "-o", merged, t1, t0}).empty());
  REQUIRE(outputOf({"render", scene, "32", "24", "-o", one}).empty());
  CHECK(rt::test::readAll(merged) == rt::test::readAll(one));
  CHECK(outputOf({"merge", "-o", dir.file("again.png"), merged, "--for", scene, "32", "24"}).empty());
}

TEST_CASE("image commands: an output that is an input, under any name, is refused before anything is written") {
  const rt::test::TempDir dir;
  const std::string scene = dir.write("scene.png", kScene);
  REQUIRE(link(scene.c_str(), dir.file("other.png").c_str()) == 0);
  for (const char* command : {"render", "raycast"}) {
    CHECK(errorOf({command, scene, "8", "6", "-o", dir.file("other.png")}) ==
          "cannot write '" + dir.file("other.png") + "': it is the scene file, which the image would replace");
  }
  const std::string t0 = dir.file("t0.exr"), t1 = dir.file("t1.exr");
  REQUIRE(outputOf({"render", scene, "8", "6", "--tile", "0/2", "-o", t0}).empty());
  REQUIRE(outputOf({"render", scene, "8", "6", "--tile", "1/2", "-o", t1}).empty());
  const std::string before = rt::test::readAll(t1);
  CHECK(errorOf({"merge", "-o", dir.file("./t1.exr"), t0, t1}) ==
        "-o '" + dir.file("./t1.exr") + "' is the tile '" + t1 + "': merge would replace it (name another file)");
  CHECK(rt::test::readAll(t1) == before);
  CHECK(rt::test::readAll(scene) == kScene);
}

TEST_CASE("image commands: --version, help <command> and <command> --help") {
  CHECK(outputOf({"--version"}) == std::string("raytrace ") + RAYTRACE_VERSION + "\n");
  const std::string render = outputOf({"help", "render"});
  CHECK(render.rfind("usage: raytrace render <scene> [<width> <height>] [options]\n", 0) == 0);
  CHECK(render.find("--tile I/N") != std::string::npos);
  CHECK(outputOf({"render", "--help"}) == render);
  CHECK(outputOf({"render", "s.pov", "-ss=2", "--help"}) == render);
  const std::string sceneinfo = outputOf({"sceneinfo", "--help"});
  CHECK(sceneinfo.rfind("usage: raytrace sceneinfo <scene> [options]\n", 0) == 0);
  CHECK(sceneinfo.find("--tile") == std::string::npos);
  CHECK(outputOf({"help", "merge"}).rfind("usage: raytrace merge -o <image> <tile.exr>... [--threads N] [--for ", 0) == 0);
  CHECK(errorOf({"help"}) == "help takes one command, as in: raytrace help render");
  CHECK(rt::usage().find("raytrace merge -o <image> <tile.exr>...") != std::string::npos);
}

TEST_CASE("image commands: with --gi-cache, tiles merge into the one-machine bytes and pixelcolor prints the rendered pixel") {
  // Each tile and each pixel command builds the whole picture's cache first (docs/gi.md), so all agree.
  const rt::test::TempDir dir;
  const std::string scene = dir.write("s.pov", kScene);
  const std::vector<std::string> gi{"-gi", "-gi_samples=8,2", "--gi-cache=0.3"};
  const auto with = [&](std::vector<std::string> args) {
    args.insert(args.end(), gi.begin(), gi.end());
    return args;
  };
  const std::string whole = dir.file("whole.png"), exact = dir.file("whole.exr");
  REQUIRE(outputOf(with({"render", scene, "40", "30", "-o", whole})).empty());
  REQUIRE(outputOf(with({"render", scene, "40", "30", "-o", exact})).empty());
  std::vector<std::string> merge{"merge", "-o", dir.file("merged.png")};
  for (int i = 2; i >= 0; --i) {
    const std::string tile = dir.file("t" + std::to_string(i) + ".exr");
    REQUIRE(outputOf(with({"render", scene, "40", "30", "--threads", std::to_string(1 + i), "--tile",
                           std::to_string(i) + "/3", "-o", tile}))
                .empty());
    merge.push_back(tile);
  }
  REQUIRE(outputOf(merge).empty());
  CHECK(rt::test::readAll(dir.file("merged.png")) == rt::test::readAll(whole));
  const rt::ExrImage image = rt::readExr(exact);
  for (const auto& [x, y] : {std::pair{20, 15}, std::pair{5, 3}, std::pair{30, 8}}) {
    const rt::Color c = image.pixels.at(x, y);
    const auto byte = [](float v) { return std::to_string(rt::toByte(v, rt::Dialect::course().toByte())); };
    const std::string printed = outputOf(with({"pixelcolor", scene, "40", "30", std::to_string(x), std::to_string(y)}));
    CAPTURE(x, y, printed);
    REQUIRE(printed.find("No Hit") == std::string::npos);
    CHECK(printed.find("Color: (" + byte(c.r) + ", " + byte(c.g) + ", " + byte(c.b) + ")") != std::string::npos);
  }
}

TEST_CASE("image commands: a scene's radiosity block is drawn by render and by pixelcolor alike") {
  // A closed sphere (kd 0.5, emission 0.2, recursion_limit 2) is 0.2·(1 + 0.5 + 0.25) = 0.35 everywhere, byte
  // 160 in sRGB, as POV-Ray 3.7 draws it; without the block it would be its emission alone (0.2, byte 124).
  const rt::test::TempDir dir;
  const std::string scene = dir.write(
      "furnace.pov", "#version 3.7;\nglobal_settings { assumed_gamma 1 radiosity { } }\ncamera { location 0 look_at z }\n"
                     "sphere { 0, 10 pigment { rgb 1 } finish { ambient 0.3 diffuse 0.5 emission 0.2 } }\n");
  CHECK(outputOf({"render", scene, "4", "3", "-o", dir.file("f.exr"), "--threads", "2"}).empty());
  const rt::ExrImage image = rt::readExr(dir.file("f.exr"));
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) CHECK(image.pixels.at(x, y).g == Approx(0.35f).epsilon(1e-5));
  }
  CHECK(outputOf({"pixelcolor", scene, "4", "3", "1", "1"}).find("Color: (160, 160, 160)") != std::string::npos);
}
