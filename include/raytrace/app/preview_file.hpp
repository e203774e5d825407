// --preview FILE: the picture so far written to FILE every few seconds while render runs, for image viewers
// that reload the file when it changes.
#pragma once

#include <condition_variable>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>

#include "raytrace/app/live_picture.hpp"

namespace rt {

class PreviewFile {
 public:
  // Starts writing `picture` to `path` every `seconds` (while rows have arrived since the last write). A write
  // that fails is reported once on `errors`, and previewing stops; the render goes on.
  PreviewFile(const LivePicture& picture, std::string path, Dialect::ToByte mode, std::ostream& errors,
              double seconds = 3);
  // Writes the picture as it stands one last time and stops.
  ~PreviewFile();
  PreviewFile(const PreviewFile&) = delete;
  PreviewFile& operator=(const PreviewFile&) = delete;

  // Writes the picture now: each write replaces the file whole (a temporary file renamed), so a viewer never
  // reads half of one.
  void write();

 private:
  const LivePicture& picture_;
  std::string path_;
  Dialect::ToByte mode_;
  std::ostream& errors_;
  bool failed_ = false;
  uint64_t written_ = 0;  // the rows the file last written holds
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace rt
