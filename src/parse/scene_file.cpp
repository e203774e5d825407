#include "raytrace/parse/scene_file.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "raytrace/parse/cs3451_parser.hpp"
#include "raytrace/util/limits.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/util/path.hpp"
#include "raytrace/parse/pov_parser.hpp"

namespace rt {

namespace {

// The pieces a file is read in, handed out to the threads: a 3 MB file is shared out too.
constexpr size_t kReadPiece = size_t(1) << 20;

// Closes the descriptor however readFile() leaves.
struct FileDescriptor {
  int fd;
  ~FileDescriptor() { close(fd); }
};

}  // namespace

// POSIX calls rather than a stream, so that every failure has its errno and a FIFO or a device is refused
// instead of read forever (O_NONBLOCK keeps the open of a FIFO without a writer from hanging).
FileText readFile(const std::string& path, int threads) {
  const FileDescriptor file{open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) throw Error("cannot open '" + path + "': " + std::strerror(errno));
  struct stat st;
  if (fstat(file.fd, &st) != 0) throw Error("cannot read '" + path + "': " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw Error("cannot read '" + path + "': it is a directory, not a scene file");
  if (!S_ISREG(st.st_mode)) throw Error("cannot read '" + path + "': it is not a regular file");
  if (std::uint64_t(st.st_size) > kMaxSceneFileBytes) {
    throw Error("cannot read '" + path + "': it is larger than " + std::to_string(kMaxSceneFileBytes >> 20) +
                " MiB, the most a scene file may have");
  }
  const size_t size = size_t(st.st_size);
  FileText text(size);
  // Pieces read on the threads at once. Most of a read's time is the kernel faulting in the fresh pages it
  // copies into, one at a time per thread (docs/performance-notes.md, "Reading a file on threads").
  std::vector<size_t> got((size + kReadPiece - 1) / kReadPiece);
  parallelForChunks(size, kReadPiece, threads, [&](size_t begin, size_t end) {
    size_t& done = got[begin / kReadPiece];
    while (begin + done < end) {
      const ssize_t n = pread(file.fd, text.data() + begin + done, end - begin - done, off_t(begin + done));
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw Error("cannot read '" + path + "': " + std::strerror(errno));
      if (n == 0) break;  // the file shrank since fstat: what is there is read
      done += size_t(n);
    }
  });
  // Up to the first piece that came short.
  size_t length = 0;
  for (const size_t n : got) {
    length += n;
    if (n < kReadPiece) break;
  }
  text.resize(length);
  return text;
}

SceneLanguage sceneLanguage(const std::string& path, std::string_view text) {
  const std::string ext = extension(path);
  if (ext == "pov") return SceneLanguage::Pov;
  if (ext == "cli") return SceneLanguage::Cs3451;
  return looksLikeCs3451(text) ? SceneLanguage::Cs3451 : SceneLanguage::Pov;
}

SceneDesc loadScene(const std::string& path, int threads) {
  const FileText file = readFile(path, threads);
  const std::string_view text = file.view();
  return sceneLanguage(path, text) == SceneLanguage::Cs3451 ? parseCs3451(text, path) : parsePov(text, path, threads);
}

}  // namespace rt
