// POV-Ray's own command line: each switch's mapping to raytrace's render words, .ini files with sections, an
// animation's frames and clocks as POV-Ray 3.7 computes them (checked with `povray` and a #debug of them), and
// every error with its whole message.
#include <catch2/catch.hpp>

#include <algorithm>
#include <sstream>

#include "raytrace/app/arguments.hpp"
#include "raytrace/app/commands.hpp"
#include "raytrace/app/povray_command_line.hpp"
#include "raytrace/parse/scene_file.hpp"
#include "raytrace/util/message.hpp"
#include "command_error.hpp"
#include "temp_dir.hpp"

using rt::test::errorOf;
using rt::test::readAll;
using rt::test::TempDir;

namespace {

// The render words a POV-Ray command line makes, joined by blanks, and its one image's name.
std::string wordsOf(const std::vector<std::string>& args) {
  std::string joined;
  for (const std::string& w : rt::readPovRayCommandLine(args).words) joined += (joined.empty() ? "" : " ") + w;
  return joined;
}

std::string outputOf(const std::vector<std::string>& args) {
  const rt::PovRayJob job = rt::readPovRayCommandLine(args);
  REQUIRE(job.frames.size() == 1);
  return job.frames[0].output;
}

// A scene whose sphere moves with the clock, so that each frame is a picture of its own.
const char* const kMovingScene =
    "#version 3.7;\n"
    "camera { location <0,0,-6> look_at 0 }\n"
    "light_source { <5,5,-5> rgb 1 }\n"
    "sphere { <2*clock - 1, 0, 0>, 1 pigment { rgb <1, frame_number/3, clock_delta> } }\n";

}  // namespace

TEST_CASE("povcli: which command lines are POV-Ray's", "[povcli]") {
  CHECK(rt::isPovRayCommandLine({"+Ia.pov"}));
  CHECK(rt::isPovRayCommandLine({"-D", "+Ia.pov"}));
  CHECK(rt::isPovRayCommandLine({"res.ini"}));
  CHECK(rt::isPovRayCommandLine({"RES.INI[Low]"}));
  CHECK(rt::isPovRayCommandLine({"input_file_name=a.pov"}));
  CHECK_FALSE(rt::isPovRayCommandLine({"render", "a.pov"}));
  CHECK_FALSE(rt::isPovRayCommandLine({"--version"}));
  CHECK_FALSE(rt::isPovRayCommandLine({}));
}

TEST_CASE("povcli: each switch's render words", "[povcli]") {
  // POV-Ray's defaults without an .ini file: 320 x 240, a PNG named after the scene in the current folder.
  CHECK(wordsOf({"+Ia.pov"}) == "render a.pov 320 240");
  CHECK(outputOf({"+Iscenes/a.pov"}) == "a.png");
  CHECK(wordsOf({"+Iscenes/a.pov", "+W64", "+H48", "+L/inc", "Declare=R=2", "+WT2", "+D", "+A0.3"}) ==
        "render scenes/a.pov 64 48 -L /inc -D R=2 --threads 2 --display --aa=1 --aa-threshold=0.3 --aa-depth=3 "
        "--jitter=1");
  // The last of a repeated option counts, as in POV-Ray; -D and -A turn the display and anti-aliasing off.
  CHECK(wordsOf({"+Ia.pov", "+W8", "+w16", "+D", "-D", "+A", "-A"}) == "render a.pov 16 240");
  // Anti-aliasing's settings, as the manual's "Anti-Aliasing Options": -An.n sets the threshold for a later +A;
  // +J with no amount keeps the previous one, and an amount of 0 or less turns jitter off.
  CHECK(wordsOf({"+Ia.pov", "+A0.1", "+AM2", "+R4", "-J"}) ==
        "render a.pov 320 240 --aa=2 --aa-threshold=0.1 --aa-depth=4");
  CHECK(wordsOf({"+Ia.pov", "-A0.2", "+J0.5", "-J", "+J", "+A"}) ==
        "render a.pov 320 240 --aa=1 --aa-threshold=0.2 --aa-depth=3 --jitter=0.5");
  CHECK(wordsOf({"+Ia.pov", "+A", "+J-1"}) == "render a.pov 320 240 --aa=1 --aa-threshold=0.3 --aa-depth=3");
  CHECK(wordsOf({"+Ia.pov", "Antialias=on", "Sampling_Method=2", "Antialias_Depth=2", "Antialias_Threshold=0",
                 "Jitter=off", "Jitter_Amount=0.25"}) == "render a.pov 320 240 --aa=2 --aa-threshold=0 --aa-depth=2");
  CHECK(wordsOf({"+Ia.pov", "+AM2", "+R5"}) == "render a.pov 320 240");
  // Verbosity and the text streams are POV-Ray's own: accepted and ignored.
  CHECK(wordsOf({"+Ia.pov", "+V", "-V", "-GA", "+GS", "-GW", "-P"}) == "render a.pov 320 240");
  // raytrace's own options keep their meaning among POV-Ray's.
  CHECK(wordsOf({"+Ia.pov", "-fresnel", "--threads", "3", "-ss=2"}) == "render a.pov 320 240 -fresnel --threads 3 -ss=2");
  CHECK(outputOf({"+Ia.pov", "-o", "x.hdr"}) == "x.hdr");
  // +F picks the format and the extension; +O without it gets it added, as POV-Ray does ("out.exr.png").
  CHECK(outputOf({"+Ia.pov", "+FE"}) == "a.exr");
  CHECK(outputOf({"+Ia.pov", "+FH"}) == "a.hdr");
  CHECK(outputOf({"+Ia.pov", "+FN8"}) == "a.png");
  CHECK(outputOf({"+Ia.pov", "+Oout"}) == "out.png");
  CHECK(outputOf({"+Ia.pov", "+Oout.PNG"}) == "out.PNG.png");
  CHECK(outputOf({"+Ia.pov", "+Oout.exr"}) == "out.exr.png");
  CHECK(outputOf({"+Ia.pov", "+Orenders/"}) == "renders/a.png");
  CHECK(outputOf({"+I\"my scene.pov\""}) == "my scene.png");
  // A part: pixels counted from 1 (inclusive), or fractions of the side, as --region's from 0 (exclusive end).
  CHECK(wordsOf({"+Ia.pov", "+W8", "+H6", "+FE", "+SC2", "+EC0.5", "+SR0.5", "+ER6"}) ==
        "render a.pov 8 6 --region 1,3,4,6");
  CHECK(wordsOf({"+Ia.pov", "+W8", "+H6", "+FE", "+EC1"}) == "render a.pov 8 6 --region 0,0,1,6");
  // As `povray` renders them: +SR0.5 +ER0.9 are rows 3 and 4 of 6, +SC0.3 +EC0.6 columns 2 and 3 of 8.
  CHECK(wordsOf({"+Ia.pov", "+W8", "+H6", "+FE", "+SR0.5", "+ER0.9", "+SC0.3", "+EC0.6"}) ==
        "render a.pov 8 6 --region 2,3,4,5");
  // The clock of one picture; POV-Ray sets clock_on for it too.
  const rt::PovRayJob still = rt::readPovRayCommandLine({"+Ia.pov", "+K0.25"});
  CHECK((still.frames[0].clock.clock == 0.25 && still.frames[0].clock.on && !still.animation));
  CHECK(still.frames[0].output == "a.png");
}

TEST_CASE("povcli: .ini files, their sections, comments and nesting", "[povcli]") {
  TempDir dir;
  const std::string ini = dir.write("res.ini",
                                    "; RES.INI, as in POV-Ray's manual\n"
                                    "Input_File_Name=scene.pov ; the scene\n"
                                    "+W120 +H100  ; the unlabeled part\n"
                                    "[Low]\n"
                                    "width = 80\r\n"
                                    "Height=60\n"
                                    "Antialias=on\n"
                                    "Display=Off\n"
                                    "[Really High]\n"
                                    "+W800 +H600\n");
  CHECK(wordsOf({ini}) == "render scene.pov 120 100");
  // A section: only its lines, and labels in any case.
  CHECK(wordsOf({"+Ia.pov", ini + "[low]"}) ==
        "render a.pov 80 60 --aa=1 --aa-threshold=0.3 --aa-depth=3 --jitter=1");
  CHECK(wordsOf({"+I" + ini + "[Really High]", "+Ia.pov"}) == "render a.pov 800 600");
  // Later options replace an .ini file's; an .ini file named on a line of another is read there.
  CHECK(wordsOf({ini, "+W10"}) == "render scene.pov 10 100");
  const std::string outer = dir.write("outer.ini", "+H7\n" + dir.file("res") + "\nOutput_File_Type=E\n");
  CHECK(wordsOf({outer}) == "render scene.pov 120 100");
  CHECK(outputOf({outer}) == "scene.exr");

  CHECK(errorOf({ini + "[Medium]"}) == "'" + ini + "' has no section '[Medium]'");
  CHECK(errorOf({dir.file("missing.ini")}) == "cannot open '" + dir.file("missing.ini") + "': No such file or directory");
  CHECK(errorOf({dir.write("typo.ini", "+Ia.pov\nWidht=8\n")}) ==
        dir.file("typo.ini") + ":2: unknown option 'Widht': did you mean 'Width'?");
  CHECK(errorOf({dir.write("q.ini", "+Ia.pov\n\nQuality=9\n")}) == dir.file("q.ini") + ":3: 'Quality=9' is not supported yet");
  CHECK(errorOf({dir.write("d.ini", "Display=maybe\n")}) == dir.file("d.ini") + ":1: Display must be on or off, found 'maybe'");
  CHECK(errorOf({dir.write("self.ini", dir.file("self.ini") + "\n")}).find("is more than 10 .ini files deep") !=
        std::string::npos);
}

TEST_CASE("povcli: an animation's frames, clocks and numbered names", "[povcli]") {
  const rt::PovRayJob job = rt::readPovRayCommandLine({"+Ia.pov", "+KFI0", "+KFF3"});
  REQUIRE(job.frames.size() == 4);
  CHECK(job.animation);
  for (int f = 0; f < 4; ++f) {
    const rt::povray::Clock& c = job.frames[f].clock;
    CHECK(job.frames[f].output == "a" + std::to_string(f) + ".png");
    CHECK(c.clock == Approx(f / 3.0));
    CHECK(c.delta == Approx(1 / 3.0));
    CHECK((c.on && c.frame == f && c.initialFrame == 0 && c.finalFrame == 3));
  }
  // Cyclic: the clock stops one step short of +KF, and POV-Ray's final_frame is one past +KFF.
  const rt::PovRayJob cyclic = rt::readPovRayCommandLine({"+Ia.pov", "+KFI0", "+KFF3", "+KC"});
  CHECK(cyclic.frames.back().clock.clock == 0.75);
  CHECK(cyclic.frames.back().clock.finalFrame == 4);
  // A subset of frames 1 to 12 (the default initial frame is 1), numbered to the width of the final frame.
  const rt::PovRayJob subset =
      rt::readPovRayCommandLine({"+Ia.pov", "+KFF12", "+KI2", "+KF3", "+SF1", "+EF2", "+Oout.png"});
  REQUIRE(subset.frames.size() == 2);
  CHECK(subset.frames[0].output == "out01.png");
  CHECK(subset.frames[1].output == "out02.png");
  CHECK(subset.frames[1].clock.clock == Approx(2 + 1 / 11.0));
  // Fractions of the 10 frames, as `povray` renders them: frames 5 and 6, then frames 3 to 6.
  CHECK(rt::readPovRayCommandLine({"+Ia.pov", "+KFF10", "+SF0.5", "+EF0.6"}).frames.size() == 2);
  const rt::PovRayJob third = rt::readPovRayCommandLine({"+Ia.pov", "+KFF10", "+SF0.33", "+EF0.67"});
  CHECK((third.frames.front().clock.frame == 3 && third.frames.back().clock.frame == 6));
  // Cyclic frames 0 to 9 are numbered to the width of POV-Ray's final frame, 10.
  CHECK(rt::readPovRayCommandLine({"+Ia.pov", "+KFI0", "+KFF9", "+KC"}).frames[0].output == "a00.png");
  // One frame: POV-Ray's clock is NaN, ours the initial clock.
  CHECK(rt::readPovRayCommandLine({"+Ia.pov", "+KFI5", "+KFF5", "+KI0.5"}).frames[0].clock.clock == 0.5);
  CHECK(rt::readPovRayCommandLine({"+Ia.pov", "+KFI5", "+KFF5"}).frames[0].output == "a5.png");
}

TEST_CASE("povcli: a 4-frame animation is 4 renders with the clock set", "[povcli]") {
  TempDir dir;
  const std::string scene = dir.write("moving.pov", kMovingScene);
  std::ostringstream out, err;
  REQUIRE(rt::runCommand({"+I" + scene, "+W16", "+H12", "-V", "+KFI0", "+KFF3", "+O" + dir.file("anim")}, out, err) == 0);
  CHECK(dir.names() == std::vector<std::string>{"anim0.png", "anim1.png", "anim2.png", "anim3.png", "moving.pov"});
  const rt::PovRayJob job = rt::readPovRayCommandLine({"+I" + scene, "+KFI0", "+KFF3"});
  for (int f = 0; f < 4; ++f) {
    rt::Words words = rt::readWords({"render", scene, "16", "12", "-o", dir.file("single.png")}, 1);
    words.load.clock = job.frames[f].clock;
    REQUIRE(rt::renderWords(words, out, err) == 0);
    const std::string frame = readAll(dir.file("anim" + std::to_string(f) + ".png"));
    CHECK(frame == readAll(dir.file("single.png")));
    if (f > 0) CHECK(frame != readAll(dir.file("anim" + std::to_string(f - 1) + ".png")));
  }
}

TEST_CASE("povcli: the scene sees each built-in of its frame", "[povcli]") {
  TempDir dir;
  // Frame 2 of +KFI0 +KFF3 +KI1 +KF4: POV-Ray's #debug shows these values.
  const std::string scene = dir.write("values.pov",
                                      "#version 3.7;\n"
                                      "#if (clock != 3 | clock_delta != 1 | frame_number != 2 | clock_on != 1 |\n"
                                      "     initial_frame != 0 | final_frame != 3 | initial_clock != 1 | final_clock != 4)\n"
                                      "  #error \"not frame 2's values\"\n"
                                      "#end\n"
                                      "sphere { 0, 1 }\n");
  rt::LoadOptions load;
  load.clock = rt::readPovRayCommandLine({"+Ia.pov", "+KFI0", "+KFF3", "+KI1", "+KF4"}).frames[2].clock;
  CHECK_NOTHROW(rt::loadScene(scene, 1, load));
  CHECK_THROWS(rt::loadScene(scene, 1, rt::LoadOptions{}));
}

TEST_CASE("povcli: a frame that fails leaves the frames before it written", "[povcli]") {
  TempDir dir;
  const std::string scene =
      dir.write("fails.pov", std::string("#if (frame_number = 2) #error \"boom\" #end\n") + kMovingScene);
  CHECK(errorOf({"+I" + scene, "+W8", "+H6", "+KFI0", "+KFF3", "+O" + dir.file("f")}) ==
        "frame 2 failed, the frames before it are written: " + scene + ":1:24: error: boom");
  CHECK(dir.names() == std::vector<std::string>{"f0.png", "f1.png", "fails.pov"});
}

TEST_CASE("povcli: bad POV-Ray command lines write nothing", "[povcli]") {
  TempDir dir;
  const std::string scene = dir.write("a.pov", kMovingScene);
  const std::string out = "+O" + dir.file("out.png");
  const auto error = [&](std::vector<std::string> args) {
    args.insert(args.begin(), "+I" + scene);
    args.push_back(out);
    return errorOf(args);
  };
  CHECK(error({"+W0"}) == "+W must be between 1 and 32768, found 0");
  CHECK(error({"Height=x"}) == "Height must be a whole number, found 'x'");
  CHECK(error({"Declare=R"}) == "Declare needs NAME=VALUE, found 'R'");
  CHECK(error({"+KFF2", "+KFI3"}) == "the final frame (+KFF2) is before the initial frame (+KFI3)");
  CHECK(error({"+KFF0"}) == "the final frame (+KFF0) is before the initial frame (1 by default)");
  CHECK(error({"+KFF9", "+SF5", "+EF4"}) == "the last frame to render (+EF4) is before the first (+SF5)");
  CHECK(error({"+KI0.5"}) == "'+KI0.5' is for an animation: give +KFI and +KFF too");
  CHECK(error({"+KFF3", "+K0.5"}) == "+K sets the clock of one picture, but +KFI and +KFF ask for an animation");
  CHECK(error({"+Q9"}) == "'+Q9' is not supported yet");
  CHECK(error({"+AMx"}) == "'+AMx' is not supported yet");
  CHECK(error({"+AM3"}) == "+AM must be between 1 and 2, found 3");
  CHECK(error({"+R0"}) == "+R must be between 1 and 9, found 0");
  CHECK(error({"+A3.5"}) == "+A must be between 0 and 3, found '3.5'");
  CHECK(error({"+J2"}) == "+J must be at most 1, found '2'");
  CHECK(error({"+AG2.2"}) == "'+AG2.2' is not supported yet");
  CHECK(error({"+D0"}) == "'+D0' is not supported yet");
  CHECK(error({"+FT"}) == "'+FT' is not supported yet");
  CHECK(error({"-F"}) == "'-F' is not supported yet");
  CHECK(error({"+P"}) == "'+P' is not supported yet");
  CHECK(error({"+A0.x"}) == "+A must be a number, found '0.x'");
  CHECK(error({"-o", "x.png"}) == "-o and +O both name the image: give one");
  CHECK(errorOf({"+I" + scene, "+FE", "-o", dir.file("x.png")}) == "-o's extension and +F both pick the format: give one");
  CHECK(error({"--thread", "2"}) == "unknown option '--thread': did you mean '--threads'? (see raytrace --help)");
  CHECK(error({"+SR2"}) == "+SR, +ER, +SC and +EC render a part of the picture, written as an OpenEXR tile: give +FE");
  CHECK(error({"+FE", "+SR2", "--region", "0,0,1,1"}) ==
        "+SR, +ER, +SC or +EC and --region both name the part to render: give one");
  CHECK(error({"+FE", "+W8", "+SC5", "+EC0.5"}) == "'+EC0.5' ends the part to render before it starts");
  CHECK(errorOf({"+W8"}) == "no scene to render: give +Iscene.pov or Input_File_Name=scene.pov");
  CHECK(errorOf({"+I" + scene, "+KFF2", "-o", dir.file("x.png")}) ==
        "-o names one image, but an animation's are numbered: name them with +O");
  CHECK(dir.names() == std::vector<std::string>{"a.pov"});
}

TEST_CASE("povcli: a frame as tiles, merged by the frame's switches; --manifest lists what it read and wrote",
          "[povcli]") {
  TempDir dir;
  const std::string include = dir.write("moving.inc", "#declare R = 1;\n");
  const std::string scene = dir.write("moving.pov", std::string("#include \"moving.inc\"\n") + kMovingScene);
  const std::vector<std::string> animation{"+I" + scene, "+W16", "+H12", "+KFI0", "+KFF3"};
  const auto with = [&](std::vector<std::string> more) {
    more.insert(more.begin(), animation.begin(), animation.end());
    return more;
  };
  std::ostringstream out, err;
  REQUIRE(rt::runCommand(with({"+O" + dir.file("anim")}), out, err) == 0);
  // One frame of the animation (+SF = +EF) is one image, which -o may name: here a tile of it.
  for (const char* i : {"0", "1"}) {
    REQUIRE(rt::runCommand(with({"+SF2", "+EF2", "--tile", std::string(i) + "/2", "-o", dir.file("t" + std::string(i) + ".exr")}),
                           out, err) == 0);
  }
  // Without -o, merge names the picture as the frame's switches do.
  REQUIRE(rt::runCommand({"merge", dir.file("t0.exr"), dir.file("t1.exr"), "--manifest", dir.file("merged.txt"),
                          "--for", "+I" + scene, "+W16", "+H12", "+KFI0", "+KFF3", "+SF2", "+EF2",
                          "+O" + dir.file("tiled")},
                         out, err) == 0);
  CHECK(readAll(dir.file("tiled2.png")) == readAll(dir.file("anim2.png")));
  CHECK(readAll(dir.file("merged.txt")) == scene + "\n" + include + "\n" + dir.file("t0.exr") + "\n" +
                                               dir.file("t1.exr") + "\n" + dir.file("tiled2.png") + "\n");
  REQUIRE(rt::runCommand(with({"+SF1", "+EF1", "+O" + dir.file("anim"), "--manifest", dir.file("frame.txt")}), out,
                         err) == 0);
  CHECK(readAll(dir.file("frame.txt")) == scene + "\n" + include + "\n" + dir.file("anim1.png") + "\n");
  // A tile records its frame's clock: merged as another frame's, it is refused.
  CHECK(errorOf({"merge", dir.file("t0.exr"), dir.file("t1.exr"), "--for", "+I" + scene, "+W16", "+H12", "+KFI0",
                 "+KFF3", "+SF1", "+EF1", "+O" + dir.file("wrong")}) ==
        rt::quote(dir.file("t0.exr"), rt::kMaxQuotedPath) + " is not a tile of the render asked for: its raytrace.clock is 'frame 2 of 0 to 3; clock "
            "0.66666666666666663, delta 0.333333...', not 'frame 1 of 0 to 3; clock 0.33333333333333331, delta "
            "0.333333...'");
  // And its -D declarations, which change the scene as its files do.
  CHECK(errorOf({"merge", dir.file("t0.exr"), dir.file("t1.exr"), "--for", "+I" + scene, "+W16", "+H12", "+KFI0",
                 "+KFF3", "+SF2", "+EF2", "Declare=R=2", "+O" + dir.file("wrong")}) ==
        rt::quote(dir.file("t0.exr"), rt::kMaxQuotedPath) +
            " is not a tile of the render asked for: its raytrace.declares is none, not 'R=2'");
  CHECK(errorOf({"merge", dir.file("t0.exr"), dir.file("t1.exr"), "--for", "+I" + scene, "+KFI0", "+KFF3"}) ==
        "merge's --for names one picture, but it renders 4 frames: give one with +SF and +EF");
  CHECK(errorOf(with({"+O" + dir.file("all"), "--manifest", dir.file("all.txt")})) ==
        "--manifest lists the files of one picture, but this animation renders 4 frames: give one with +SF and +EF");
  CHECK(errorOf(with({"+SF1", "+EF1", "+O" + dir.file("anim"), "--manifest"})) == "--manifest needs a value");
  const std::vector<std::string> names = dir.names();
  CHECK(std::find(names.begin(), names.end(), "wrong1.png") == names.end());
}
