#include "raytrace/util/limits.hpp"

#include <algorithm>
#include <fstream>
#include <limits>

#include <sys/resource.h>
#include <unistd.h>

namespace rt {

std::uint64_t availableMemory() {
  std::uint64_t bytes = std::numeric_limits<std::uint64_t>::max();
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  while (meminfo >> key >> kib) {
    if (key == "MemAvailable:") {
      bytes = kib * 1024;
      break;
    }
    meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  if (bytes == std::numeric_limits<std::uint64_t>::max()) {  // no /proc: what the C library knows
    bytes = std::uint64_t(sysconf(_SC_AVPHYS_PAGES)) * std::uint64_t(sysconf(_SC_PAGESIZE));
  }
  // Under `ulimit -v` what is left is the limit less the address space already in use (statm's first field).
  rlimit limit{};
  std::uint64_t usedPages = 0;
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      std::ifstream("/proc/self/statm") >> usedPages) {
    const std::uint64_t used = usedPages * std::uint64_t(sysconf(_SC_PAGESIZE));
    bytes = std::min<std::uint64_t>(bytes, limit.rlim_cur > used ? limit.rlim_cur - used : 0);
  }
  return bytes;
}

std::string memoryShortage(const std::string& what, std::uint64_t needed, std::uint64_t available) {
  if (needed <= available) return "";
  const auto mib = [](std::uint64_t b) { return std::to_string((b + (1 << 20) - 1) >> 20); };
  return what + " needs " + mib(needed) + " MiB of memory, but only " + std::to_string(available >> 20) +
         " MiB are available";
}

std::string objectMemoryShortage(std::uint64_t previous, std::uint64_t count, const std::string& what) {
  std::uint64_t power = 65536;
  if (count < power) return "";
  while (power <= count / 2) power *= 2;  // the largest power of two not above count
  if (previous >= power) return "";
  return memoryShortage(what + " beyond " + std::to_string(power) + " objects", power * kBytesPerObject,
                        availableMemory());
}

}  // namespace rt
