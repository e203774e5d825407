#include "raytrace/image/image.hpp"

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

#include "raytrace/util/error.hpp"
#include "raytrace/util/limits.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/image/png.hpp"

namespace rt {

namespace {

// What a PNG of the 8-bit pixels takes besides them: its compressed segments and the file, each about 3 bytes
// a pixel at most.
constexpr std::uint64_t kRgb8BytesPerPixel = 9;

void checkMemory(int width, int height, std::uint64_t bytesPerPixel) {
  const std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(height) * bytesPerPixel;
  const std::string what = "a " + std::to_string(width) + "x" + std::to_string(height) + " image";
  const std::string shortage = memoryShortage(what, bytes, availableMemory());
  if (!shortage.empty()) throw Error(shortage);
}

}  // namespace

Image::Image(int width, int height) : width_(width), height_(height) {
  // The float pixels, then the 8-bit ones writePng makes of them.
  checkMemory(width, height, sizeof(Color) + kRgb8BytesPerPixel);
  static_assert(std::is_trivially_copyable_v<Color>, "pixels start as calloc's zero bytes");
  pixels_.reset(static_cast<Color*>(std::calloc(size_t(width) * size_t(height), sizeof(Color))));
  if (!pixels_) throw std::bad_alloc();
}

Rgb8Image::Rgb8Image(int width, int height) : width_(width), height_(height) {
  checkMemory(width, height, kRgb8BytesPerPixel);
  bytes_.reset(new unsigned char[size_t(width) * size_t(height) * 3]);
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

void toBytes(const float* in, size_t count, unsigned char* out, Conventions::ToByte mode) {
  for (size_t i = 0; i < count; ++i) out[i] = toByte(in[i], mode);
}

void writePng(const Image& image, const std::string& path, Conventions::ToByte mode, int threads) {
  Rgb8Image bytes(image.width(), image.height());
  parallelFor(image.height(), threads, [&](int y) {
    static_assert(sizeof(Color) == 3 * sizeof(float), "a row of pixels is 3·width floats in a row");
    toBytes(glm::value_ptr(image.at(0, y)), size_t(image.width()) * 3, bytes.at(0, y), mode);
  });
  writePng(bytes, path, threads);
}

void writePng(const Rgb8Image& image, const std::string& path, int threads) {
  const std::vector<unsigned char> png = encodePng(image.data(), image.width(), image.height(), threads);
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
