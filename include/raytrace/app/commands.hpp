// The command line: `raytrace <command> <scene> [width height [x y]] [flags]`.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace rt {

// Runs one command with its arguments (argv without the program name). Data goes to `out`, warnings to `err`.
// Returns the exit status; user errors are thrown as Error and reported by main().
int runCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

// The usage text that `raytrace --help` prints.
std::string usage();

}  // namespace rt
