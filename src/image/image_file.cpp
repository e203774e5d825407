#include "raytrace/image/image_file.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "raytrace/image/exr_file.hpp"
#include "raytrace/image/hdr_file.hpp"
#include "raytrace/image/output_file.hpp"
#include "raytrace/image/png_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/parallel.hpp"

namespace rt {

namespace {

bool endsWith(const std::string& s, const char* suffix) {
  const std::string end(suffix);
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

}  // namespace

ImageFormat imageFormat(const std::string& path) {
  if (endsWith(path, ".png")) return ImageFormat::Png;
  if (endsWith(path, ".hdr")) return ImageFormat::Hdr;
  if (endsWith(path, ".exr")) return ImageFormat::Exr;
  const size_t slash = path.rfind('/'), dot = path.rfind('.');
  const bool extension = dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
  throw Error("cannot write '" + path + "': " +
              (extension ? "unknown image format '" + path.substr(dot) + "'" : std::string("no image format")) +
              " (name it .png, .hdr or .exr)");
}

void checkImagePath(const std::string& path) {
  imageFormat(path);
  checkWritableFolder(path);
}

void writeImage(const Image& image, const std::string& path, Conventions::ToByte mode, int threads) {
  switch (imageFormat(path)) {
    case ImageFormat::Png: {
      Rgb8Image bytes(image.width(), image.height());
      parallelFor(image.height(), threads, [&](int y) {
        static_assert(sizeof(Color) == 3 * sizeof(float), "a row of pixels is 3·width floats in a row");
        toBytes(glm::value_ptr(image.at(0, y)), size_t(image.width()) * 3, bytes.at(0, y), mode);
      });
      writePng(bytes, path);
      return;
    }
    case ImageFormat::Hdr: writeHdr(image, path); return;
    case ImageFormat::Exr: writeExr(image, path); return;
  }
}

}  // namespace rt
