// The progress line of a long render: percent done, time elapsed and left, eye rays per second, rewritten in
// place.
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>
#include <ostream>

namespace rt {

class ProgressMeter {
 public:
  // Reports on `totalPixels` pixels of `raysPerPixel` eye rays each to `out`, or nowhere when it is null.
  ProgressMeter(std::ostream* out, int64_t totalPixels, int raysPerPixel);
  // Erases the line, so that the terminal is left as it was.
  ~ProgressMeter();
  ProgressMeter(const ProgressMeter&) = delete;
  ProgressMeter& operator=(const ProgressMeter&) = delete;

  // Counts `pixels` more as done; any thread may call it. The line is rewritten at most every kInterval.
  void add(int64_t pixels);

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kInterval{250};

  std::ostream* out_;
  int64_t total_;
  int raysPerPixel_;
  std::mutex mutex_;
  int64_t done_ = 0;
  Clock::time_point start_ = Clock::now(), shown_ = start_;
  bool anything_ = false;  // whether a line was printed that the destructor must erase
};

}  // namespace rt
