// raytrace_manual: writes raytrace.1, the bash completion or the zsh completion to standard output, for the
// build to install (CMakeLists.txt).
#include <cstring>
#include <iostream>

#include "raytrace/app/manual.hpp"

int main(int argc, char** argv) {
  if (argc == 2 && std::strcmp(argv[1], "man") == 0) std::cout << rt::manPage();
  else if (argc == 2 && std::strcmp(argv[1], "bash") == 0) std::cout << rt::bashCompletion();
  else if (argc == 2 && std::strcmp(argv[1], "zsh") == 0) std::cout << rt::zshCompletion();
  else {
    std::cerr << "usage: raytrace_manual man|bash|zsh\n";
    return 2;
  }
  return std::cout.flush() ? 0 : 1;
}
