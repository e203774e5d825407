#include "raytrace/util/progress.hpp"

#include <cstdio>

namespace rt {

ProgressMeter::ProgressMeter(std::ostream* out, int64_t totalPixels, int raysPerPixel)
    : out_(out), total_(totalPixels), raysPerPixel_(raysPerPixel) {}

ProgressMeter::~ProgressMeter() {
  if (anything_) *out_ << "\r\033[K" << std::flush;  // carriage return, then ANSI "erase to end of line"
}

void ProgressMeter::add(int64_t pixels) {
  if (!out_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  done_ += pixels;
  const Clock::time_point now = Clock::now();
  if (now - shown_ < kInterval || done_ >= total_) return;
  shown_ = now;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  const double rate = double(done_) * raysPerPixel_ / seconds;
  const double left = seconds * double(total_ - done_) / double(done_);
  char line[128];
  std::snprintf(line, sizeof line, "\r\033[Krender: %3d%%  %.0f s elapsed, %.0f s left  %.2f M eye rays/s",
                int(100 * done_ / total_), seconds, left, rate / 1e6);
  *out_ << line << std::flush;
  anything_ = true;
}

}  // namespace rt
