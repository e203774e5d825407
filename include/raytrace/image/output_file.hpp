// A file that appears whole or not at all: written under a temporary name beside its target, then renamed over
// it. The previous file at the target stays intact until the rename, and on any failure or interruption.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rt {

class OutputFile {
 public:
  // Creates the temporary file in the target's folder. Its name is random, short (within NAME_MAX however
  // long the target's is) and created with O_EXCL|O_NOFOLLOW, so that nothing planted at it, a symbolic link
  // included, is ever written through. Throws Error ("cannot write 'path': …").
  explicit OutputFile(const std::string& path);
  // Removes the temporary file unless commit() succeeded.
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(const void* data, size_t size);
  // Flushes the data to the disk and renames the file into place.
  void commit();

 private:
  void discard();  // closes and removes the temporary file, if still there
  [[noreturn]] void fail(int error);
  std::string path_, temp_;
  int fd_ = -1;
  bool pending_ = false;  // the temporary file exists and is ours to remove
};

// `bytes` written as the file at `path` through an OutputFile.
void writeFile(const std::string& path, const std::vector<unsigned char>& bytes);

// Throws the Error writing `path` would meet in its folder (missing, not a folder, not writable), or at the
// path itself (something there that is not a regular file or a symbolic link, or a read-only file, which
// renaming over it would replace without a word), so that a command can report it before it spends any time
// rendering.
void checkWritableFolder(const std::string& path);

}  // namespace rt
