// Wall time of a program's steps, for --stats.
#pragma once

#include <chrono>

namespace rt {

// Wall time in seconds since the stopwatch was made or last read.
class Stopwatch {
 public:
  double lap() {
    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_ = Clock::now();
};

}  // namespace rt
