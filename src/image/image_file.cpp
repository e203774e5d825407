#include "raytrace/image/image_file.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "raytrace/image/exr_file.hpp"
#include "raytrace/image/hdr_file.hpp"
#include "raytrace/image/output_file.hpp"
#include "raytrace/image/png_file.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/message.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/util/path.hpp"

namespace rt {

ImageFormat imageFormat(const std::string& path) {
  const std::string ext = extension(path);
  if (ext == "png") return ImageFormat::Png;
  if (ext == "hdr") return ImageFormat::Hdr;
  if (ext == "exr") return ImageFormat::Exr;
  throw Error("cannot write " + quote(path, kMaxQuotedPath) + ": " +
              (ext.empty() ? std::string("no image format") : "unknown image format " + quote("." + ext)) +
              " (name it .png, .hdr or .exr)");
}

void checkImagePath(const std::string& path) {
  imageFormat(path);
  checkWritableFolder(path);
}

void writeImage(const Image& image, const std::string& path, Dialect::ToByte mode, int threads) {
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
