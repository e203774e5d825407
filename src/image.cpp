#include "raytrace/image.hpp"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include <unistd.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include "raytrace/error.hpp"
#include "raytrace/limits.hpp"

namespace rt {

Image::Image(int width, int height) : width_(width), height_(height) {
  // The float pixels and the 8-bit copy that writePng makes of them.
  const std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(height) * (sizeof(Color) + 3);
  const std::string what = "a " + std::to_string(width) + "x" + std::to_string(height) + " image";
  const std::string shortage = memoryShortage(what, bytes, availableMemory());
  if (!shortage.empty()) throw Error(shortage);
  pixels_.assign(size_t(width) * size_t(height), Color(0));
}

unsigned char toByte(float c, Conventions::ToByte mode) {
  const float v = std::isnan(c) ? 0.0f : glm::clamp(c, 0.0f, 1.0f) * 255.0f;
  return static_cast<unsigned char>(mode == Conventions::ToByte::Round ? std::lround(v) : int(v));
}

namespace {

// A short write sets the stream's error flag, which writePng checks once at the end.
void appendToFile(void* context, void* data, int size) {
  std::fwrite(data, 1, size_t(size), static_cast<std::FILE*>(context));
}

}  // namespace

void writePng(const Image& image, const std::string& path, Conventions::ToByte mode) {
  std::vector<unsigned char> bytes;
  bytes.reserve(size_t(image.width()) * image.height() * 3);
  for (int y = image.height() - 1; y >= 0; --y) {
    for (int x = 0; x < image.width(); ++x) {
      const Color& c = image.at(x, y);
      for (int k = 0; k < 3; ++k) bytes.push_back(toByte(c[k], mode));
    }
  }
  const std::string temp = path + ".tmp" + std::to_string(getpid());
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) throw Error("cannot write '" + path + "': " + std::strerror(errno));
  const int ok = stbi_write_png_to_func(appendToFile, f, image.width(), image.height(), 3, bytes.data(),
                                        image.width() * 3);
  const bool failed = !ok || std::ferror(f) || std::fflush(f) != 0 || fsync(fileno(f)) != 0;
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
