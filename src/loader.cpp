#include "raytrace/loader.hpp"

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "raytrace/cli_parser.hpp"
#include "raytrace/limits.hpp"
#include "raytrace/pov_parser.hpp"

namespace rt {

namespace {

// Closes the descriptor however readFile() leaves.
struct FileDescriptor {
  int fd;
  ~FileDescriptor() { close(fd); }
};

}  // namespace

// POSIX calls rather than a stream, so that every failure has its errno and a FIFO or a device is refused
// instead of read forever (O_NONBLOCK keeps the open of a FIFO without a writer from hanging).
FileText readFile(const std::string& path) {
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
  size_t done = 0;
  while (done < size) {
    const ssize_t n = read(file.fd, text.data() + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw Error("cannot read '" + path + "': " + std::strerror(errno));
    if (n == 0) break;  // the file shrank since fstat: parse what is there
    done += size_t(n);
  }
  text.resize(done);
  return text;
}

std::string extension(const std::string& path) {
  const size_t dot = path.find_last_of("./");
  const bool named = dot != std::string::npos && dot > 0 && path[dot] == '.' && path[dot - 1] != '/';
  std::string ext = named ? path.substr(dot + 1) : "";
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

SceneLanguage sceneLanguage(const std::string& path, std::string_view text) {
  const std::string ext = extension(path);
  if (ext == "pov") return SceneLanguage::Pov;
  if (ext == "cli") return SceneLanguage::Cli;
  return looksLikeCli(text) ? SceneLanguage::Cli : SceneLanguage::Pov;
}

SceneDesc loadScene(const std::string& path, int threads) {
  const FileText file = readFile(path);
  const std::string_view text = file.view();
  return sceneLanguage(path, text) == SceneLanguage::Cli ? parseCli(text, path) : parsePov(text, path, threads);
}

}  // namespace rt
