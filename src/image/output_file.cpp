#include "raytrace/image/output_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "raytrace/image/interrupt_cleanup.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"

namespace rt {

namespace {

// The folder part of `path`, with its slash ("" for a bare name, "/" for the root's files).
std::string folderOf(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? "" : path.substr(0, slash + 1);
}

// 16 random hex digits: no other process guesses the name, and an O_EXCL collision is retried.
std::string randomName() {
  static std::random_device device;
  const unsigned long long r = (static_cast<unsigned long long>(device()) << 32) ^ device();
  char name[32];
  std::snprintf(name, sizeof name, ".raytrace-%016llx", r);
  return name;
}

[[noreturn]] void cannotWrite(const std::string& path, int error) {
  throw Error("cannot write " + quote(path, kMaxQuotedPath) + ": " + std::strerror(error));
}

}  // namespace

OutputFile::OutputFile(const std::string& path) : path_(path) {
  for (int attempt = 0; fd_ < 0; ++attempt) {
    temp_ = folderOf(path) + randomName();
    registerTemporary(temp_);
    // The mode goes through the umask, as a file made by fopen's would.
    fd_ = open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ < 0) {
      const int error = errno;
      clearTemporary();
      if (error != EEXIST || attempt == 100) cannotWrite(path, error);
    }
  }
  pending_ = true;
}

OutputFile::~OutputFile() { discard(); }

void OutputFile::discard() {
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
  if (!pending_) return;
  unlink(temp_.c_str());
  clearTemporary();
  pending_ = false;
}

void OutputFile::fail(int error) {
  discard();
  cannotWrite(path_, error);
}

void OutputFile::write(const void* data, size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd_, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(n < 0 ? errno : EIO);
    p += n;
    size -= size_t(n);
  }
}

void OutputFile::commit() {
  if (fsync(fd_) != 0) fail(errno);
  const int closed = close(fd_);
  fd_ = -1;
  if (closed != 0 || std::rename(temp_.c_str(), path_.c_str()) != 0) fail(errno);
  pending_ = false;
  clearTemporary();
}

void writeFile(const std::string& path, const std::vector<unsigned char>& bytes) {
  OutputFile file(path);
  file.write(bytes.data(), bytes.size());
  file.commit();
}

void checkWritableFolder(const std::string& path) {
  const std::string folder = folderOf(path);
  const std::string name = folder.empty() ? "." : folder;
  struct stat st {};
  if (stat(name.c_str(), &st) != 0) cannotWrite(path, errno);
  if (!S_ISDIR(st.st_mode)) cannotWrite(path, ENOTDIR);
  if (access(name.c_str(), W_OK | X_OK) != 0) cannotWrite(path, errno);
  struct stat there {};
  if (lstat(path.c_str(), &there) != 0 || S_ISLNK(there.st_mode)) return;
  if (!S_ISREG(there.st_mode)) {
    throw Error("cannot write " + quote(path, kMaxQuotedPath) + ": something other than a file is there");
  }
  if (!(there.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH))) {
    throw Error("cannot write " + quote(path, kMaxQuotedPath) + ": it is read-only (make it writable to replace it)");
  }
}

}  // namespace rt
