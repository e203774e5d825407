// #fopen, #read, #write and #fclose against what real POV-Ray 3.7 wrote and read for the same lines, and the
// rules that keep a scene's files safe: confined to the image's folder, on disk only once the scene has parsed.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "raytrace/app/commands.hpp"
#include "raytrace/parse/povray/interpreter.hpp"
#include "temp_dir.hpp"

namespace rt::povray {
namespace {

struct Parsed {
  std::string out;  // what #debug printed, then the error if the scene failed
  std::vector<DataFileDesc> files;
};

// Runs `text` as "scene.pov", finding data files through -L `dir` and writing into `dir`.
Parsed parse(const std::string& text, const test::TempDir& dir, bool anywhere = false) {
  std::ostringstream out;
  InterpreterOptions options;
  options.debug = &out;
  options.libraryPaths = {dir.path()};
  options.writeFolder = dir.path();
  options.writeAnywhere = anywhere;
  Interpreter interpreter(options);
  const auto ignore = [](const std::shared_ptr<const Node>&) {};
  try {
    interpreter.run("scene.pov", text, ignore, ignore);
  } catch (const Error& e) {
    return {out.str() + e.what(), {}};
  }
  return {out.str(), interpreter.takeDataFiles()};
}

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST_CASE("povray: #write then #read gives POV-Ray's text and values", "[povray]") {
  const test::TempDir dir;
  const Parsed p = parse(R"POV(#version 3.7;
#fopen F "data.txt" write
#write (F, "\"Testing 123\",", 5, ",", <1,2,3>, ",", str(1/3,0,3), ",", 1/3, ",", -2.5e-7, ",", <1.5,-2>, ",", 2147483648, ",", -0, ",\n")
#fclose F
#fopen F "data.txt" append
#write (F "\"more\"" "\n")
#fclose F
#fopen F "data.txt" read
#read (F, S, A, V, T, B, C, W, D, Z)
#debug concat(S, "|", str(A,0,-1), "|", vstr(3,V,",",0,-1), "|", str(T,0,-1), "|", str(B,0,-1), "|", str(C*1e7,0,-1), "|", vstr(2,W,",",0,-1), "|", str(D,0,0), "|", str(Z,0,1), "|", str(defined(F),0,0), "\n")
#read (F, M, N)
#debug concat(M, "|", str(defined(F),0,0), "|", str(defined(N),0,0), "\n")
)POV", dir);
  // What POV-Ray 3.7 wrote in data.txt and printed.
  CHECK(p.out ==
        "Testing 123|5.000000|1.000000,2.000000,3.000000|0.333000|0.333333|-2.500000|1.500000,-2.000000|2147480000|-0.0|1\n"
        "more|0|0\n");
  REQUIRE(p.files.size() == 1);
  CHECK(p.files[0].path == dir.file("data.txt"));
  CHECK(p.files[0].text == "\"Testing 123\",5,<1,2,3> ,0.333,0.333333,-2.5e-07,<1.5,-2> ,2.14748e+09,-0,\n\"more\"\n");
  CHECK(p.files[0].loc.str() == "scene.pov:2:1");
  CHECK(dir.names().empty());  // nothing on disk: the caller decides
}

TEST_CASE("povray: #write's binary words write bytes as POV-Ray does, up to the next comma", "[povray]") {
  const test::TempDir dir;
  const Parsed p = parse("#fopen F \"bin.dat\" write\n"
                         "#write (F, uint8 300, sint8 -200, uint16be 258.4, sint16le -2, sint32be <1,-2>, \"x\", 65.6, uint8 65.5 66)\n",
                         dir);
  REQUIRE(p.files.size() == 1);
  // od -tx1 of POV-Ray's file.
  const unsigned char bytes[] = {0xff, 0x80, 0x01, 0x02, 0xfe, 0xff, 0x00, 0x00, 0x00, 0x01, 0xff,
                                 0xff, 0xff, 0xfe, 0x78, 0x36, 0x35, 0x2e, 0x36, 0x42, 0x42};
  CHECK(p.files[0].text == std::string(reinterpret_cast<const char*>(bytes), sizeof bytes));
}

TEST_CASE("povray: #read past the end closes the file and leaves the rest as they were", "[povray]") {
  const test::TempDir dir;
  dir.write("one.txt", "1");
  dir.write("three.txt", "1, \"a\", <1,2,3>\n");
  // POV-Ray 3.7: B keeps 7, C stays undefined, and the identifier of the file is gone.
  CHECK(parse("#declare B = 7;\n#fopen R \"one.txt\" read\n#read (R, A, B, C)\n"
              "#debug concat(str(A,0,0), str(B,0,0), str(defined(C),0,0), str(defined(R),0,0))\n",
              dir).out == "1700");
  CHECK(parse("#fopen R \"three.txt\" read\n#declare N = 0;\n"
              "#while (defined(R)) #read (R, A) #declare N = N + 1; #end\n#debug str(N,0,0)\n",
              dir).out == "3");
  // An empty file is closed by the first #read, as is one that ends in a comma once its values are read.
  dir.write("empty.txt", "");
  dir.write("comma.txt", "1,2,");
  CHECK(parse("#fopen R \"empty.txt\" read\n#read (R, A)\n#ifndef (A) #ifndef (R) #debug \"closed\" #end #end\n", dir).out ==
        "closed");
  CHECK(parse("#fopen R \"comma.txt\" read\n#read (R, A, B)\n#debug str(defined(R),0,0)\n", dir).out == "0");
  // #fclose of a file that is not open does nothing, as in POV-Ray.
  CHECK(parse("#fclose Nope\n#debug \"ok\"\n", dir).out == "ok");
}

TEST_CASE("povray: #include reads a file the scene wrote earlier; append keeps what the file held", "[povray]") {
  const test::TempDir dir;
  CHECK(parse("#fopen F \"made.inc\" write\n#write (F, \"#declare Made = \", 6 * 7, \";\\n\")\n#fclose F\n"
              "#include \"made.inc\"\n#debug str(Made,0,0)\n",
              dir).out == "42");
  dir.write("log.txt", "old\n");
  const Parsed p = parse("#fopen F \"log.txt\" append\n#write (F, \"new\\n\")\n", dir);
  REQUIRE(p.files.size() == 1);
  CHECK(p.files[0].text == "old\nnew\n");
  CHECK(parse("#fopen F \"\" write\n", dir).out == "scene.pov:1:10: error: #fopen needs a file name, found an empty string");
}

TEST_CASE("povray: file directives that cannot be carried out stop the scene with one located message", "[povray]") {
  const test::TempDir dir;
  dir.write("bad.txt", "1,,2");
  dir.write("short.txt", "<1>");
  dir.write("open.txt", "\"never closed");
  dir.write("word.txt", "1, Two");
  const auto error = [&](const std::string& text) { return parse(text, dir).out; };
  CHECK(error("#fopen F \"nope.txt\" read\n") == "scene.pov:1:10: error: cannot find the file 'nope.txt' to read");
  CHECK(error("#fopen F \"bad.txt\" read\n#read (F, A, B)\n") ==
        "bad.txt:1:3: error: expected a float, a vector or a string, found ',' (read at scene.pov:2:1)");
  CHECK(error("#fopen F \"word.txt\" read\n#read (F, A, B)\n") ==
        "word.txt:1:4: error: expected a float, a vector or a string, found 'Two' (read at scene.pov:2:1)");
  CHECK(error("#fopen F \"short.txt\" read\n#read (F, A)\n") ==
        "short.txt:1:4: error: a vector has 2 to 5 components, found 1 (read at scene.pov:2:1)");
  CHECK(error("#fopen F \"open.txt\" read\n") ==
        "open.txt:1:1: error: this string is not closed (read at scene.pov:1:1)");
  CHECK(error("#fopen F \"bad.txt\" read\n#write (F, 1)\n") ==
        "scene.pov:2:9: error: #write needs a file opened for write or append, but 'F' is opened for reading");
  CHECK(error("#fopen F \"out.txt\" write\n#read (F, A)\n") ==
        "scene.pov:2:8: error: #read needs a file opened for read, but 'F' is opened for writing");
  CHECK(error("#read (G, A)\n") == "scene.pov:1:8: error: undeclared identifier 'G'");
  CHECK(error("#declare G = 1;\n#fclose G\n") == "scene.pov:2:9: error: 'G' is a float, not a file #fopen opened");
  CHECK(error("#fopen F \"out.txt\" writ\n") ==
        "scene.pov:1:20: error: expected read, write or append after the file name, found 'writ'");
  CHECK(error("#fopen F \"out.txt\" write\n#write (F, rgb 1)\n") ==
        "scene.pov:2:12: error: #write writes floats, vectors and strings, found a colour");
  CHECK(error("#fopen F 3 write\n") == "scene.pov:1:10: error: #fopen needs a file name, found a float");
}

TEST_CASE("povray: #fopen writes only in the image's folder unless --allow-write-anywhere", "[povray]") {
  const test::TempDir dir, away;
  REQUIRE(symlink(away.path().c_str(), dir.file("link").c_str()) == 0);
  CHECK(parse("#fopen F \"../x.txt\" write\n", dir).out ==
        "scene.pov:1:10: error: #fopen may only write a file in the folder of the output image and below, found "
        "'../x.txt' (--allow-write-anywhere allows it)");
  CHECK(parse("#fopen F \"/tmp/x.txt\" append\n", dir).out ==
        "scene.pov:1:10: error: #fopen may only write a file in the folder of the output image and below, found "
        "'/tmp/x.txt' (--allow-write-anywhere allows it)");
  CHECK(parse("#fopen F \"link/x.txt\" write\n", dir).out ==
        "scene.pov:1:10: error: #fopen names 'link/x.txt', but a folder on its way is a symbolic link out of the "
        "folder of the output image (--allow-write-anywhere allows it)");
  const Parsed p = parse("#fopen F \"link/x.txt\" write\n#fopen G \"" + away.file("y.txt") + "\" write\n", dir, true);
  REQUIRE(p.files.size() == 2);
  CHECK(p.files[0].path == dir.file("link/x.txt"));
  CHECK(p.files[1].path == away.file("y.txt"));
}

TEST_CASE("povray: a #write loop past 256 MiB stops with a message", "[povray]") {
  const test::TempDir dir;
  CHECK(parse("#declare S = \"0123456789abcdef\";\n#for (I, 1, 16) #declare S = concat(S, S); #end\n"  // 1 MiB
              "#fopen F \"big.txt\" write\n#for (I, 1, 300)\n#write (F, S)\n#end\n",
              dir).out == "scene.pov:5:1: error: #write writes more than the 256 MiB a scene may write");
}

TEST_CASE("povray: render puts the scene's files beside the image only when the whole run succeeds", "[povray]") {
  const test::TempDir dir;
  const std::string writes = "#version 3.7;\n#fopen F \"data.txt\" write\n#write (F, \"new\")\n#fclose F\n";
  const std::string good = dir.write("good.pov", writes + "sphere { 0, 1 }\n");
  const std::string bad = dir.write("bad.pov", writes + "sphere { 0, Oops }\n");
  const std::string out = dir.file("out");
  REQUIRE(mkdir(out.c_str(), 0755) == 0);
  std::ostringstream o, e;
  // The data file beside -o, which is in another folder than the scene.
  REQUIRE(runCommand({"render", good, "4", "3", "-o", out + "/image.png"}, o, e) == 0);
  CHECK(contents(out + "/data.txt") == "new");
  // A parse that fails later leaves the file written before as it was; so does a diagnostic command.
  dir.write("out/data.txt", "old");
  CHECK_THROWS_WITH(runCommand({"render", bad, "4", "3", "-o", out + "/image2.png"}, o, e),
                    bad + ":5:13: error: undeclared identifier 'Oops'");
  CHECK(runCommand({"sceneinfo", good}, o, e) == 0);
  CHECK(contents(out + "/data.txt") == "old");
  // A file that would replace the scene or the image is refused before anything is rendered.
  const std::string self = dir.write("self.pov", "#version 3.7;\n#fopen F \"self.pov\" write\n#fclose F\n");
  CHECK_THROWS_WITH(runCommand({"render", self, "4", "3", "-o", dir.file("self.png")}, o, e),
                    self + ":2:1: error: #fopen would replace the scene file '" + self + "'");
  const std::string image = dir.write("image.pov", "#version 3.7;\n#fopen F \"image.png\" write\n#fclose F\n");
  CHECK_THROWS_WITH(runCommand({"raycast", image, "4", "3", "-o", dir.file("image.png")}, o, e),
                    image + ":2:1: error: #fopen would replace the image '" + dir.file("image.png") + "'");
  CHECK(dir.names() == std::vector<std::string>{"bad.pov", "good.pov", "image.pov", "out", "self.pov"});
}

TEST_CASE("povray: the files a scene reads are noted once each, in the order first found", "[povray]") {
  const test::TempDir dir;
  dir.write("a.inc", "#declare A = 1;\n");
  dir.write("b.inc", "#include \"a.inc\"\n");
  dir.write("data.txt", "7,\n");
  InterpreterOptions options;
  options.libraryPaths = {dir.path()};
  Interpreter interpreter(options);
  const auto ignore = [](const std::shared_ptr<const Node>&) {};
  interpreter.run("scene.pov",
                  "#version 3.7;\n#include \"b.inc\"\n#include \"a.inc\"\n#fopen F \"data.txt\" read\n"
                  "#read (F, N)\n#fclose F\n#if (file_exists(\"none.inc\")) #end\n",
                  ignore, ignore);
  CHECK(interpreter.takeFilesFound() ==
        std::vector<std::string>{dir.file("b.inc"), dir.file("a.inc"), dir.file("data.txt")});
}

}  // namespace
}  // namespace rt::povray
