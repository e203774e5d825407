// POV-Ray's height_field (the manual's §3.4.5.1.5): the unit square x, z in [0, 1] raised to the heights of an
// image's pixels, y in [0, 1], two triangles to each square of four neighbouring pixels.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "raytrace/shapes/triangle_mesh.hpp"
#include "raytrace/surface/function.hpp"

namespace rt {

// An image's heights in [0, 1], row by row from the image's top row, as the manual reads a pixel: a palette
// image's index over 255, a grey image's value over its largest, and a colour image's red and green as the
// high and low bytes of a 16-bit number.
struct HeightImage {
  int width = 0, height = 0;
  std::vector<double> heights;
};

// The heights of the image file at `path`, a Fractint `pot` file when `pot`; a ParseError at `at` when it cannot
// be read.
HeightImage readHeightImage(const std::string& path, const SourceLoc& at, bool pot = false);

// The heights of POV-Ray's `function W, H { … }`: f(x, y, 0) at x = i/(W − 1), y = j/(H − 1), the row j = 0 the
// image's top row, kept in 16 bits as POV-Ray keeps them; a ParseError at `at` when the size is below 2 by 2 or
// does not fit in memory.
HeightImage functionHeights(const Function& f, double width, double height, const SourceLoc& at);

// The triangles over `image`: smooth ones with normals from the neighbouring heights when `smooth`; the
// squares wholly below `waterLevel` left out.
MeshData heightFieldMesh(const HeightImage& image, bool smooth, double waterLevel);

// `height_field { [type] "file" | function W, H { … } [smooth] [water_level w] [hierarchy b] … }`.
template <class Reader> MeshData readHeightField(Reader& r) {
  static constexpr std::string_view kTypes[] = {"exr", "gif", "hdr", "iff", "jpeg", "pgm", "png",
                                                "pot", "ppm", "sys", "tga", "tiff"};
  bool pot = false;
  for (std::string_view type : kTypes) {
    if (r.keyword(type)) {
      pot = type == "pot";
      break;
    }
  }
  const SourceLoc at = r.here();
  HeightImage image;
  std::shared_ptr<const Function> f;
  double width = 0, height = 0;
  if (r.imageFunction(f, width, height)) {
    // A refused function, reported once the file is read, stands as a flat field until then.
    image = f ? functionHeights(*f, width, height, at) : HeightImage{2, 2, {0, 0, 0, 0}};
  } else {
    const std::string name = r.string("the height field's image file");
    const std::string path = r.findFile(name);
    if (path.empty()) throw ParseError(at, "cannot find the height field image \"" + name + "\"");
    image = readHeightImage(path, at, pot);
  }
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
  return heightFieldMesh(image, smooth, waterLevel);
}

}  // namespace rt
