// An image in linear float colour and its safe conversion to an 8-bit PNG file.
#pragma once

#include <cstdlib>
#include <memory>
#include <string>

#include "raytrace/math.hpp"
#include "raytrace/scene_desc.hpp"

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

 private:
  struct Free {
    void operator()(Color* p) const { std::free(p); }
  };
  int width_, height_;
  // Top row first, as PNG stores them; all black to start with. From calloc, whose large blocks are fresh
  // zero pages: nothing is written until the render threads write their own pixels. Filling a vector
  // would write every page first, on one thread (7 ms at 1280×960).
  std::unique_ptr<Color[], Free> pixels_;
};

// One colour channel to a byte: clamp to [0,1], then round (course §a.0) or truncate (.cli §A.4).
unsigned char toByte(float c, Conventions::ToByte mode);

// Writes the image as PNG at `path` without ever leaving a partial file there: it is written beside the
// target under a temporary name and renamed over it only once complete. `threads` compress in parallel; the
// file is the same for any number. Throws Error on failure.
void writePng(const Image& image, const std::string& path, Conventions::ToByte mode, int threads = 1);

}  // namespace rt
