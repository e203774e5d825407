// The command line: `raytrace <command> <scene> [width height [x y]] [flags]`.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace rt {

// Runs one command with its arguments (argv without the program name). Data goes to `out`, warnings to `err`.
// Returns the exit status; user errors are thrown as Error and reported by main().
int runCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

struct Words;

// The render command with `words` read from its arguments (readWords), for a command line of another program's
// (povray_command_line.hpp).
int renderWords(const Words& words, std::ostream& out, std::ostream& err);

// The usage text that `raytrace --help` prints.
std::string usage();

// What the man page and the shell completions say about a command (from the command table).
struct CommandSummary {
  std::string name;
  std::string usage;    // "raytrace render <scene> [<width> <height>] [options]"
  std::string summary;  // what it does, in one line
  bool readsScene;      // takes a scene and the options; merge and help take their own words
  bool writesImage;     // takes the image options too
  bool isRender;        // takes the options only render takes (Scope::Render)
};
std::vector<CommandSummary> commandSummaries();

}  // namespace rt
