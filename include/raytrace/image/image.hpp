// Images in linear float colour and in the 8 bits a PNG file holds.
#pragma once

#include <cstdlib>
#include <memory>
#include <string>

#include "raytrace/geometry/math.hpp"
#include "raytrace/scene/dialect.hpp"

namespace rt {

class Image {
 public:
  // Throws Error, before taking any memory, when the machine lacks the memory for the image (limits.hpp).
  Image(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  // Pixel (x, y) with y growing upward, as the course numbers pixels (§a.0).
  Color& at(int x, int y) { return pixels_[size_t(height_ - 1 - y) * width_ + x]; }
  const Color& at(int x, int y) const { return pixels_[size_t(height_ - 1 - y) * width_ + x]; }
  // Every pixel, top row first.
  Color* data() { return pixels_.get(); }
  const Color* data() const { return pixels_.get(); }

 private:
  struct Free {
    void operator()(Color* p) const { std::free(p); }
  };
  int width_, height_;
  // Top row first, as PNG stores them; all black to start with. From calloc, whose large blocks are fresh
  // zero pages: nothing is written until the render threads write their own pixels. Filling a vector
  // would write every page first, on one thread (docs/performance-notes.md, "The image's memory").
  std::unique_ptr<Color[], Free> pixels_;
};

// 8-bit RGB pixels, three bytes each, top row first: what a PNG file holds. renderRgb8 writes its tiles straight
// into one, so that no float image is kept: more pages to fault in and a pass of its own to convert
// (docs/performance-notes.md, "The image's memory").
class Rgb8Image {
 public:
  // Throws Error, before taking any memory, when the machine lacks the memory for the image (limits.hpp).
  Rgb8Image(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  // The first of the three bytes of pixel (x, y), y growing upward as in Image.
  unsigned char* at(int x, int y) { return bytes_.get() + (size_t(height_ - 1 - y) * width_ + x) * 3; }
  const unsigned char* data() const { return bytes_.get(); }

 private:
  int width_, height_;
  std::unique_ptr<unsigned char[]> bytes_;  // left unset: whoever makes the image writes every byte
};

// One colour channel to a byte: clamp to [0,1], then round (course §a.0) or truncate (.cli §A.4).
unsigned char toByte(float c, Dialect::ToByte mode);
// toByte() of `count` channels in a row, into `out`.
void toBytes(const float* in, size_t count, unsigned char* out, Dialect::ToByte mode);

}  // namespace rt
