#include "raytrace/image/hdr_file.hpp"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <vector>

#include "raytrace/image/stb_output.hpp"

namespace rt {

namespace {

// RGBE's largest value is about 1.7e38 (a byte's mantissa with exponent 127); stb's conversion overflows its
// exponent byte beyond.
constexpr float kLargest = 1e38f;

}  // namespace

void writeHdr(const Image& image, const std::string& path) {
  const float* in = &image.data()->r;
  std::vector<float> rgb(size_t(image.width()) * size_t(image.height()) * 3);
  // std::max(0, NaN) is 0, as 0 < NaN is false.
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = std::min(std::max(0.0f, in[i]), kLargest);
  writeWithStb(path, [&](StbWriteFunc* func, void* context) {
    return stbi_write_hdr_to_func(func, context, image.width(), image.height(), 3, rgb.data());
  });
}

}  // namespace rt
