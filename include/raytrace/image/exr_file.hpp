// OpenEXR files of 32-bit float RGB: whole renders, and the tiles of a render split over machines.
#pragma once

#include <map>
#include <string>

#include "raytrace/image/image.hpp"
#include "raytrace/image/region.hpp"

namespace rt {

// The pixels of `window` inside a width × height picture: OpenEXR's display window is the whole picture and
// its data window the part held (pbrt's convention for crops), so that a tile knows where it goes.
struct ExrImage {
  int width = 0, height = 0;
  Region window;
  Image pixels;  // window.width() × window.height(), its top row first
  std::map<std::string, std::string> attributes;  // string attributes of the header
};

// Writes the exact floats, ZIP-compressed (lossless), with the attributes as string attributes, at `path`
// through an OutputFile. Throws Error.
void writeExr(const ExrImage& image, const std::string& path);
// The same for a whole image without attributes.
void writeExr(const Image& image, const std::string& path);

// Reads a file writeExr wrote (or any losslessly compressed OpenEXR file with 32-bit float R, G and B channels;
// others are ignored), with its string attributes. Throws Error ("cannot read 'path': …"), having checked the
// header's sizes against the file before OpenEXR allocates them.
ExrImage readExr(const std::string& path);

}  // namespace rt
