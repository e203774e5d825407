// POV-Ray's image_map pigment (the manual's "Image Maps"): an image's colours laid on the unit square of x and y
// and repeated, or wrapped round the y axis on a sphere, a cylinder or a torus of major radius 1.
#pragma once

#include <string>
#include <vector>

#include "raytrace/surface/pigment.hpp"
#include "raytrace/util/error.hpp"

namespace rt {

struct ImageMap {
  enum class Mapping { Planar, Spherical, Cylindrical, Torus };
  enum class Interpolation { None, Bilinear, NormalizedDistance };
  int width = 0, height = 0;
  std::vector<Rgbft> pixels;  // row by row from the image's top row
  Mapping mapping = Mapping::Planar;
  Interpolation interpolation = Interpolation::None;
  bool once = false;  // not repeated: clear outside the image
  Rgbft extremes[2];  // the lowest and the highest of each channel, set by findExtremes()

  void findExtremes();  // once the pixels and `once` are final

  Rgbft at(const glm::dvec3& p) const;  // p in the pigment's space
};

// `filter I, F` or `transmit I, F`: the amount given to the pixels of a palette image's index I.
struct PaletteChannel {
  int index;
  bool transmit;
  float amount;
};

// An image file's pixels as scene colours (extremes not yet found), row by row from the top: an 8 or 16-bit file's values v decoded as
// v^fileGamma when fileGamma > 0, as sRGB when fileGamma == 0, and left as they are when it is < 0; then raised
// to 1 / workingGamma. A high dynamic range file's values are linear. Its alpha channel gives transmit.
// `channels` then set the filter or transmit of a palette image's pixels (and of no other image's).
// A ParseError at `at` when the file cannot be read, or has no pixels, or too many.
ImageMap readImageFile(const std::string& path, double fileGamma, double workingGamma, const SourceLoc& at,
                       const std::vector<PaletteChannel>& channels = {});

}  // namespace rt
