// Test support: the one-line error a command line gives, run in-process through runCommand.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "raytrace/app/commands.hpp"
#include "raytrace/util/error.hpp"

namespace rt::test {

// The error message a command line produces, or "" if it runs.
inline std::string errorOf(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  try {
    runCommand(args, out, err);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace rt::test
