#include "raytrace/image/png_file.hpp"

#include <stb/stb_image_write.h>

#include "raytrace/image/stb_output.hpp"

namespace rt {

namespace {

// PNG filter type 2, "Up" (§9.2): each byte minus the one above it. Smooth vertical gradients become small
// numbers that deflate well, and it needs no per-row trial of the five filters, which would take longer than
// the compression itself.
constexpr int kUpFilter = 2;

}  // namespace

void writePng(const Rgb8Image& image, const std::string& path) {
  stbi_write_force_png_filter = kUpFilter;
  writeWithStb(path, [&](StbWriteFunc* func, void* context) {
    return stbi_write_png_to_func(func, context, image.width(), image.height(), 3, image.data(), image.width() * 3);
  });
}

}  // namespace rt
