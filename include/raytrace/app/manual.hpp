// The man page and the shell completions, made from the command and option tables, so that they list exactly
// what the program takes. raytrace_manual writes them at build time; `cmake --install` installs them.
#pragma once

#include <string>

namespace rt {

// raytrace.1, in the man(7) macros.
std::string manPage();

// The bash completion (commands, options and their values, scene files *.pov and *.cli).
std::string bashCompletion();

// The same for zsh, with each command's and option's summary.
std::string zshCompletion();

}  // namespace rt
