// raytrace: the command-line entry point. The only place errors are caught.
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>

#include <malloc.h>
#include <unistd.h>

#include "raytrace/app/commands.hpp"
#include "raytrace/parse/mesh_file.hpp"
#include "raytrace/util/error.hpp"

namespace {

// Standard output flushed and closed, so that its last write error is seen too: output to a full disk or
// /dev/full is one message and exit 1, never a truncated file and exit 0.
void finishStandardOutput() {
  const auto fail = [](int error) {
    throw rt::Error(std::string("cannot write to standard output: ") + std::strerror(error ? error : EIO));
  };
  std::cout.flush();
  if (std::cout.fail()) fail(errno);
  if (std::fflush(stdout) != 0) fail(errno);
  // A standard output closed from the start (>&-) had nothing written to it: nothing was lost.
  if (close(STDOUT_FILENO) != 0 && errno != EBADF) fail(errno);
}

}  // namespace

int main(int argc, char** argv) {
  // Past a file size limit (ulimit -f) a write then fails with EFBIG, which writePng reports and cleans up
  // after, instead of the signal killing us and leaving its temporary file behind.
  std::signal(SIGXFSZ, SIG_IGN);
  // One run takes and gives back memory phase after phase: a file's parts, then the scene, its hierarchy, the
  // image and its PNG. Freed blocks up to 32 MiB (glibc's largest threshold) are kept for the next phase
  // instead of being faulted in again (docs/performance-notes.md, "Memory kept between phases").
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 32 << 20);
  try {
    std::ios::sync_with_stdio(false);  // inside: it allocates the streams' buffers, which a tight ulimit refuses
    const int status = rt::runCommand(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
    finishStandardOutput();
    return status;
  } catch (const rt::ParseError& e) {
    std::cerr << e.what() << "\n";
  } catch (const rt::MeshFileError& e) {
    std::cerr << e.what() << "\n";
  } catch (const rt::Error& e) {
    std::cerr << "raytrace: error: " << e.what() << "\n";
  } catch (const std::bad_alloc&) {
    std::cerr << "raytrace: error: out of memory\n";
  }
  return 1;
}
