// POV-Ray's height_field (the manual's §3.4.5.1.5): the unit square x, z in [0, 1] raised to the heights of an
// image's pixels, y in [0, 1], two triangles to each square of four neighbouring pixels.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "raytrace/shapes/triangle_mesh.hpp"

namespace rt {

// An image's heights in [0, 1], row by row from the image's top row, as the manual reads a pixel: a palette
// image's index over 255, a grey image's value over its largest, and a colour image's red and green as the
// high and low bytes of a 16-bit number.
struct HeightImage {
  int width = 0, height = 0;
  std::vector<double> heights;
};

// The heights of the image file at `path`; a ParseError at `at` when it cannot be read.
HeightImage readHeightImage(const std::string& path, const SourceLoc& at);

// The triangles over `image`: smooth ones with normals from the neighbouring heights when `smooth`; the
// squares wholly below `waterLevel` left out.
MeshData heightFieldMesh(const HeightImage& image, bool smooth, double waterLevel);

// `height_field { [type] "file" [smooth] [water_level w] [hierarchy b] … }`.
template <class Reader> MeshData readHeightField(Reader& r) {
  static constexpr std::string_view kTypes[] = {"exr", "gif", "hdr", "iff", "jpeg", "pgm", "png",
                                                "pot", "ppm", "sys", "tga", "tiff"};
  for (std::string_view type : kTypes) {
    if (r.keyword(type)) break;
  }
  const SourceLoc at = r.here();
  if (r.functionNext()) throw ParseError(at, "'height_field function' is not supported yet");
  const std::string name = r.string("the height field's image file");
  const std::string path = r.findFile(name);
  if (path.empty()) throw ParseError(at, "cannot find the height field image \"" + name + "\"");
  bool smooth = false;
  double waterLevel = 0;
  for (;;) {
    if (r.keyword("smooth")) {
      smooth = true;
    } else if (r.keyword("water_level")) {
      waterLevel = r.number("the water level");
    } else {
      break;
    }
  }
  return heightFieldMesh(readHeightImage(path, at), smooth, waterLevel);
}

}  // namespace rt
