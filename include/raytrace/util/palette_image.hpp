// A palette image's indices, which stb_image does not give (it turns them into the palette's colours): what a
// height field's heights are, and what an image map's `filter I, F` and `transmit I, F` name.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rt {

struct PaletteImage {
  int width = 0, height = 0;
  std::vector<int> indices;  // row by row from the image's top row
};

// The indices of a palette PNG (not interlaced) or of a GIF's first image, from the file's bytes; nothing for
// any other file.
std::optional<PaletteImage> paletteIndices(const std::string& bytes);

}  // namespace rt
