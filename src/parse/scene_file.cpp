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
#include "raytrace/util/message.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/util/path.hpp"
#include "raytrace/parse/pov_parser.hpp"
#include "raytrace/parse/povray/scene_builder.hpp"

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
  const std::string name = quote(path, kMaxQuotedPath);  // made first: it could change errno
  const FileDescriptor file{open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (file.fd < 0) throw Error("cannot open " + name + ": " + std::strerror(errno));
  struct stat st;
  if (fstat(file.fd, &st) != 0) throw Error("cannot read " + name + ": " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw Error("cannot read " + name + ": it is a directory, not a scene file");
  if (!S_ISREG(st.st_mode)) throw Error("cannot read " + name + ": it is not a regular file");
  if (std::uint64_t(st.st_size) > kMaxSceneFileBytes) {
    throw Error("cannot read " + name + ": it is larger than " + std::to_string(kMaxSceneFileBytes >> 20) +
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
      if (n < 0) throw Error("cannot read " + name + ": " + std::strerror(errno));
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

SceneLanguage povDialect(std::string_view text, DialectChoice dialect) {
  if (dialect == DialectChoice::Auto) return povray::usesPovRayLanguage(text) ? SceneLanguage::PovRay : SceneLanguage::Pov;
  return dialect == DialectChoice::PovRay ? SceneLanguage::PovRay : SceneLanguage::Pov;
}

SceneDesc loadScene(const std::string& path, int threads, const LoadOptions& options) {
  const FileText file = readFile(path, threads);
  std::string_view text = file.view();
  // A UTF-8 byte-order mark, which some editors put first, is no part of the scene in either language.
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark) text.remove_prefix(kByteOrderMark.size());
  if (sceneLanguage(path, text) == SceneLanguage::Cs3451) return parseCs3451(text, path);
  if (povDialect(text, options.dialect) == SceneLanguage::PovRay) {
    povray::PovRayOptions pov;
    pov.libraryPaths = options.libraryPaths;
    pov.imageWidth = options.width;
    pov.imageHeight = options.height;
    pov.declares = options.declares;
    pov.writeFolder = options.writeFolder;
    pov.writeAnywhere = options.writeAnywhere;
    pov.clock = options.clock;
    return povray::parsePovRay(text, path, pov);
  }
  return parsePov(text, path, threads);
}

}  // namespace rt
