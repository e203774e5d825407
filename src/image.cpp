#include "raytrace/image.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include <unistd.h>

#include "raytrace/error.hpp"
#include "raytrace/limits.hpp"
#include "raytrace/parallel.hpp"
#include "raytrace/png.hpp"

namespace rt {

Image::Image(int width, int height) : width_(width), height_(height) {
  // The float pixels and what writePng makes of them: the 8-bit pixels, their filtered rows and the
  // compressed stream, each about 3 bytes a pixel at most.
  const std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(height) * (sizeof(Color) + 9);
  const std::string what = "a " + std::to_string(width) + "x" + std::to_string(height) + " image";
  const std::string shortage = memoryShortage(what, bytes, availableMemory());
  if (!shortage.empty()) throw Error(shortage);
  pixels_.assign(size_t(width) * size_t(height), Color(0));
}

unsigned char toByte(float c, Conventions::ToByte mode) {
  const float v = std::isnan(c) ? 0.0f : glm::clamp(c, 0.0f, 1.0f) * 255.0f;
  // v ≥ 0, so truncation is floor, and v − floor(v) is exact: rounding half up is std::lround(v), inline.
  const int whole = int(v);
  const bool up = mode == Conventions::ToByte::Round && v - float(whole) >= 0.5f;
  return static_cast<unsigned char>(up ? whole + 1 : whole);
}

void writePng(const Image& image, const std::string& path, Conventions::ToByte mode, int threads) {
  const size_t stride = size_t(image.width()) * 3;
  std::vector<unsigned char> bytes(stride * size_t(image.height()));
  parallelFor(image.height(), threads, [&](int row) {  // PNG rows run top down, pixel rows y up
    unsigned char* out = bytes.data() + size_t(row) * stride;
    const int y = image.height() - 1 - row;
    for (int x = 0; x < image.width(); ++x) {
      const Color& c = image.at(x, y);
      for (int k = 0; k < 3; ++k) *out++ = toByte(c[k], mode);
    }
  });
  const std::vector<unsigned char> png = encodePng(bytes, image.width(), image.height(), threads);
  const std::string temp = path + ".tmp" + std::to_string(getpid());
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) throw Error("cannot write '" + path + "': " + std::strerror(errno));
  // A short write sets the stream's error flag, checked below.
  std::fwrite(png.data(), 1, png.size(), f);
  const bool failed = std::ferror(f) || std::fflush(f) != 0 || fsync(fileno(f)) != 0;
  const int err = errno;
  if (std::fclose(f) != 0 || failed) {
    std::remove(temp.c_str());
    throw Error("cannot write '" + path + "': " + std::strerror(err ? err : EIO));
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    const int renameErr = errno;
    std::remove(temp.c_str());
    throw Error("cannot write '" + path + "': " + std::strerror(renameErr));
  }
}

}  // namespace rt
