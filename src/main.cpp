// raytrace: the command-line entry point. The only place errors are caught.
#include <csignal>
#include <iostream>
#include <new>

#include "raytrace/cli.hpp"
#include "raytrace/error.hpp"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  // Past a file size limit (ulimit -f) a write then fails with EFBIG, which writePng reports and cleans up
  // after, instead of the signal killing us and leaving its temporary file behind.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    return rt::runCommand(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
  } catch (const rt::ParseError& e) {
    std::cerr << e.what() << "\n";
  } catch (const rt::Error& e) {
    std::cerr << "raytrace: error: " << e.what() << "\n";
  } catch (const std::bad_alloc&) {
    std::cerr << "raytrace: error: out of memory\n";
  }
  return 1;
}
