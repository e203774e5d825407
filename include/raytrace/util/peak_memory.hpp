// The most memory the process has held at once, for --stats.
#pragma once

#include <cstdint>

#include <sys/resource.h>

namespace rt {

// The peak resident set size in bytes (Linux reports it in KiB); 0 if the system does not say.
inline uint64_t peakMemory() {
  rusage usage{};
  return getrusage(RUSAGE_SELF, &usage) == 0 ? uint64_t(usage.ru_maxrss) * 1024 : 0;
}

}  // namespace rt
