#include "raytrace/app/preview_file.hpp"

#include <chrono>

#include "raytrace/image/image_file.hpp"
#include "raytrace/util/error.hpp"

namespace rt {

PreviewFile::PreviewFile(const LivePicture& picture, std::string path, Dialect::ToByte mode,
                         std::ostream& errors, double seconds)
    : picture_(picture), path_(std::move(path)), mode_(mode), errors_(errors) {
  thread_ = std::thread([this, seconds] {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return stopping_; })) {
      lock.unlock();
      write();
      lock.lock();
    }
  });
}

PreviewFile::~PreviewFile() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  thread_.join();
  write();
}

void PreviewFile::write() {
  const uint64_t rows = picture_.rowsSeen();
  if (failed_ || rows == written_) return;
  try {
    // One thread: the render's threads are busy with the pixels.
    writeImage(picture_.colors(), path_, mode_, 1);
    written_ = rows;
  } catch (const Error& e) {
    errors_ << "raytrace: warning: --preview: " << e.what() << "; no more previews\n";
    failed_ = true;
  }
}

}  // namespace rt
