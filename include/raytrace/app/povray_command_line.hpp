// POV-Ray 3.7's own command line (+Iscene.pov +W640 +H480, .ini files, +KFI0 +KFF9 …) taken as POV-Ray takes
// it: its options become the words of raytrace's render command, and an animation is one render per frame with
// the clock set as POV-Ray sets it. Each option's mapping: docs/povray-command-line.md.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "raytrace/parse/povray/clock.hpp"

namespace rt {

// One picture to render: the file it goes to and the clock its scene is read with.
struct PovRayFrame {
  std::string output;  // the scene's or +O's name with the format's extension, numbered in an animation
  povray::Clock clock;
};

// What a POV-Ray command line asks for.
struct PovRayJob {
  // raytrace's words for each frame: "render", the scene, width, height, then options; the output is the frame's.
  std::vector<std::string> words;
  std::vector<PovRayFrame> frames;  // in the order rendered; one for a still picture
  bool animation = false;           // +KFI or +KFF: the frames are numbered
};

// The usage line of POV-Ray's command line, for --help and the man page.
constexpr const char* kPovRayUsage = "raytrace +I<scene> [POV-Ray options]";

// Whether `args` (argv without the program) are in POV-Ray's style: the first is a switch (+W640, -D), an
// .ini file, or Input_File_Name=….
bool isPovRayCommandLine(const std::vector<std::string>& args);

// The job the arguments ask for, every option and .ini file read and checked, nothing rendered. Throws an Error
// naming an option raytrace does not have ("'+Q9' is not supported yet") or a bad value.
PovRayJob readPovRayCommandLine(const std::vector<std::string>& args);

// Renders the job's frames in order, each written once rendered; an Error in one names its frame and leaves the
// frames before it written.
int runPovRayCommandLine(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rt
