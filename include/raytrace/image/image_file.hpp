// Image files by their name's extension: .png (8-bit), .hdr (Radiance RGBE) and .exr (OpenEXR, 32-bit float).
#pragma once

#include <string>

#include "raytrace/image/image.hpp"
#include "raytrace/scene/dialect.hpp"

namespace rt {

enum class ImageFormat { Png, Hdr, Exr };

// The format `path` names, or an Error: "cannot write 'x.jpg': unknown image format '.jpg' (use .png, .hdr or
// .exr)".
ImageFormat imageFormat(const std::string& path);

// Throws, before anything is rendered, the Error writing an image at `path` would meet: an unknown format, a
// missing or unwritable folder.
void checkImagePath(const std::string& path);

// Writes the image in the format its name gives: PNG of its channels converted by toByte(mode) on `threads`
// threads, or the linear floats themselves. Throws Error.
void writeImage(const Image& image, const std::string& path, Dialect::ToByte mode, int threads);

}  // namespace rt
