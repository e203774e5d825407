#include "raytrace/image/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <new>
#include <type_traits>

#include "raytrace/util/error.hpp"
#include "raytrace/util/limits.hpp"

namespace rt {

namespace {

// What a PNG of the 8-bit pixels takes besides them: stb's filtered copy, libdeflate's output and stb's file,
// each about 3 bytes a pixel at most.
constexpr std::uint64_t kRgb8BytesPerPixel = 12;

void checkMemory(int width, int height, std::uint64_t bytesPerPixel) {
  const std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(height) * bytesPerPixel;
  const std::string what = "a " + std::to_string(width) + "x" + std::to_string(height) + " image";
  const std::string shortage = memoryShortage(what, bytes, availableMemory());
  if (!shortage.empty()) throw Error(shortage);
}

}  // namespace

Image::Image(int width, int height) : width_(width), height_(height) {
  // The float pixels, then the 8-bit ones and the PNG file that may be made of them.
  checkMemory(width, height, sizeof(Color) + kRgb8BytesPerPixel);
  static_assert(std::is_trivially_copyable_v<Color>, "pixels start as calloc's zero bytes");
  pixels_.reset(static_cast<Color*>(std::calloc(size_t(width) * size_t(height), sizeof(Color))));
  if (!pixels_) throw std::bad_alloc();
}

Rgb8Image::Rgb8Image(int width, int height) : width_(width), height_(height) {
  checkMemory(width, height, kRgb8BytesPerPixel);
  bytes_.reset(new unsigned char[size_t(width) * size_t(height) * 3]);
}

unsigned char toByte(float c, Dialect::ToByte mode) {
  // Branch-free, so that the conversion of a whole image vectorizes: a fractional part that is ≥ 0.5 half the
  // time is a coin toss for a branch predictor. std::max(0, NaN) is 0, as 0 < NaN is false.
  float v = std::min(std::max(0.0f, c), 1.0f);
  // The sRGB transfer function (IEC 61966-2-1), as POV-Ray 3.7 encodes a linear image.
  if (mode == Dialect::ToByte::Srgb) v = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
  v *= 255.0f;
  // Round half up (course §a.0) or truncate (.cli §A.4). A float has 24 significant bits, so v + 0.5 is exact
  // in double and rounds v as std::lround(v) would; in float, v = 0.5 − 2⁻²⁵ would round up to 1.
  const double half = mode == Dialect::ToByte::Truncate ? 0.0 : 0.5;
  return static_cast<unsigned char>(int(double(v) + half));
}

void toBytes(const float* in, size_t count, unsigned char* out, Dialect::ToByte mode) {
  for (size_t i = 0; i < count; ++i) out[i] = toByte(in[i], mode);
}

}  // namespace rt
