#include "raytrace/image.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>
#include <type_traits>

#include <glm/gtc/type_ptr.hpp>
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
  static_assert(std::is_trivially_copyable_v<Color>, "pixels start as calloc's zero bytes");
  pixels_.reset(static_cast<Color*>(std::calloc(size_t(width) * size_t(height), sizeof(Color))));
  if (!pixels_) throw std::bad_alloc();
}

unsigned char toByte(float c, Conventions::ToByte mode) {
  // Branch-free, so that the conversion of a whole image vectorizes: a fractional part that is ≥ 0.5 half the
  // time is a coin toss for a branch predictor. std::max(0, NaN) is 0, as 0 < NaN is false.
  const float v = std::min(std::max(0.0f, c), 1.0f) * 255.0f;
  // Round half up (course §a.0) or truncate (.cli §A.4). A float has 24 significant bits, so v + 0.5 is exact
  // in double and rounds v as std::lround(v) would; in float, v = 0.5 − 2⁻²⁵ would round up to 1.
  const double half = mode == Conventions::ToByte::Round ? 0.5 : 0.0;
  return static_cast<unsigned char>(int(double(v) + half));
}

void writePng(const Image& image, const std::string& path, Conventions::ToByte mode, int threads) {
  const size_t stride = size_t(image.width()) * 3;
  // Left unset, as every byte is written below, on the threads.
  const std::unique_ptr<unsigned char[]> bytes(new unsigned char[stride * size_t(image.height())]);
  parallelFor(image.height(), threads, [&](int row) {  // PNG rows run top down, pixel rows y up
    // A row of pixels is 3·width floats in a row. Locals, not the captured references, so that the byte stores
    // cannot alias them and the loop vectorizes.
    static_assert(sizeof(Color) == 3 * sizeof(float), "no padding between pixels");
    const size_t n = stride;
    const Conventions::ToByte m = mode;
    unsigned char* out = bytes.get() + size_t(row) * n;
    const float* in = glm::value_ptr(image.at(0, image.height() - 1 - row));
    for (size_t i = 0; i < n; ++i) out[i] = toByte(in[i], m);
  });
  const std::vector<unsigned char> png = encodePng(bytes.get(), image.width(), image.height(), threads);
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
