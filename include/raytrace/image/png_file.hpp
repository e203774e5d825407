// PNG files of 8-bit RGB pixels, by stb_image_write (W3C PNG specification, ISO/IEC 15948).
#pragma once

#include <string>

#include "raytrace/image/image.hpp"

namespace rt {

// Writes the image as a PNG file at `path` through an OutputFile: rows filtered with "Up", compressed by
// libdeflate's fastest level. The file's bytes depend on the pixels only. Throws Error.
void writePng(const Rgb8Image& image, const std::string& path);

}  // namespace rt
