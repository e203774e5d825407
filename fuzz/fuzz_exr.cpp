// libFuzzer target for the OpenEXR reader that merge and render --resume use on tiles (readExr). Any bytes must
// either read or throw rt::Error: any other exception, a crash, a sanitizer report, a hang or a blown memory
// limit is a finding. OpenEXR reads files by name, so each input goes through a file of this process's own.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include <unistd.h>

#include "raytrace/image/exr_file.hpp"
#include "raytrace/util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = "/tmp/raytrace-fuzz-exr-" + std::to_string(getpid()) + ".exr";
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), long(size));
  try {
    const rt::ExrImage image = rt::readExr(path);
    (void)image;
  } catch (const rt::Error&) {
  }
  return 0;
}
