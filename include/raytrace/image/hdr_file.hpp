// Radiance RGBE (.hdr) files of linear float colour, by stb_image_write.
#pragma once

#include <string>

#include "raytrace/image/image.hpp"

namespace rt {

// Writes the image's radiance, unclamped, at `path` through an OutputFile. RGBE holds non-negative finite
// values only: a negative or NaN channel is written as 0, and anything above 1e38 as 1e38. Throws Error.
void writeHdr(const Image& image, const std::string& path);

}  // namespace rt
