// raytrace: the command-line entry point. The only place errors are caught.
#include <csignal>
#include <iostream>
#include <new>

#include <malloc.h>

#include "raytrace/app/commands.hpp"
#include "raytrace/util/error.hpp"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  // Past a file size limit (ulimit -f) a write then fails with EFBIG, which writePng reports and cleans up
  // after, instead of the signal killing us and leaving its temporary file behind.
  std::signal(SIGXFSZ, SIG_IGN);
  // One run takes and gives back memory phase after phase: a file's parts, then the scene, its hierarchy, the
  // image and its PNG. Freed blocks up to 32 MiB (glibc's largest threshold) are kept for the next phase
  // instead of being faulted in again (docs/performance-notes.md, "Memory kept between phases").
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 32 << 20);
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
