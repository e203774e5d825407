#include "raytrace/shapes/height_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

// stb_image decodes the files (compiled once, in src/image/stb_image.cpp).
#include <stb/stb_image.h>

#include "raytrace/util/limits.hpp"
#include "raytrace/util/palette_image.hpp"

namespace rt {

HeightImage readHeightImage(const std::string& path, const SourceLoc& at, bool pot) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw ParseError(at, "cannot read the height field image \"" + path + "\"");
  if (pot) {
    // Fractint's continuous-potential file: a GIF twice the field's width, the high bytes of 16-bit heights in
    // its left half and their low bytes in its right half; POV-Ray 3.7 reads (high·256 + low)/65536 (its
    // trace() on mtmand.pot gives exactly these).
    const std::optional<PaletteImage> indexed = paletteIndices(bytes);
    if (!indexed || indexed->width % 2 != 0) {
      throw ParseError(at, "the pot file \"" + path + "\" is not a GIF of an even width");
    }
    const int w = indexed->width / 2;
    HeightImage image{w, indexed->height, {}};
    for (int y = 0; y < indexed->height; ++y) {
      const int* row = indexed->indices.data() + size_t(y) * size_t(indexed->width);
      for (int x = 0; x < w; ++x) image.heights.push_back((row[x] * 256 + row[w + x]) / 65536.0);
    }
    return image;
  }
  if (std::optional<PaletteImage> indexed = paletteIndices(bytes)) {
    // What POV-Ray 3.7 gives a palette index: index/256 (measured with trace() on its height fields).
    HeightImage image{indexed->width, indexed->height, {}};
    for (int index : indexed->indices) image.heights.push_back(index / 256.0);
    return image;
  }
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(data, int(bytes.size()), &w, &h, &channels)) {
    throw ParseError(at, "cannot read the height field image \"" + path + "\": " + stbi_failure_reason());
  }
  const bool grey = channels <= 2;
  stbi_us* pixels = stbi_load_16_from_memory(data, int(bytes.size()), &w, &h, &channels, grey ? 1 : 3);
  if (!pixels) throw ParseError(at, "cannot read the height field image \"" + path + "\": " + stbi_failure_reason());
  const bool sixteen = stbi_is_16_bit_from_memory(data, int(bytes.size()));
  HeightImage image{w, h, {}};
  image.heights.resize(size_t(w) * size_t(h));
  for (size_t i = 0; i < image.heights.size(); ++i) {
    // The manual's heights: a grey image's value over its largest; a colour image's red and green as the high and
    // low bytes of a 16-bit number (POV-Ray 3.7 divides it by 65536, as trace() shows).
    if (grey) {
      image.heights[i] = pixels[i] / 65535.0;
    } else {
      const int red = pixels[3 * i] >> 8, green = pixels[3 * i + 1] >> 8;
      image.heights[i] = sixteen ? pixels[3 * i] / 65535.0 : (red * 256 + green) / 65536.0;
    }
  }
  stbi_image_free(pixels);
  return image;
}

HeightImage functionHeights(const Function& f, double width, double height, const SourceLoc& at) {
  if (!(width >= 2 && height >= 2)) {
    throw ParseError(at, "a height field function's size must be at least 2 by 2, as in `function 100, 100 { … }`");
  }
  // The heights, the mesh's vertices and its triangles: about 200 bytes a point.
  const double points = std::floor(width) * std::floor(height);
  const std::string shortage =
      memoryShortage("a height field function of " + std::to_string(int64_t(std::min(points, 9e18))) + " points",
                     uint64_t(std::min(points * 200, 1.8e19)), availableMemory());
  if (!shortage.empty()) throw ParseError(at, shortage);
  const int w = int(width), h = int(height);
  HeightImage image{w, h, {}};
  image.heights.reserve(size_t(w) * size_t(h));
  for (int j = 0; j < h; ++j) {
    for (int i = 0; i < w; ++i) {
      // POV-Ray keeps each height as a 16-bit number: the value times 65535 cut toward zero, modulo 65536, and
      // reads it over 65536 (its trace() finds 32767/65536 where f = 0.5, 32769/65536 where f = −0.5).
      const double scaled = f.at({double(i) / (w - 1), double(j) / (h - 1), 0}) * 65535;
      const int64_t whole = std::abs(scaled) < 9e18 ? int64_t(scaled) : 0;
      image.heights.push_back(uint16_t(uint64_t(whole)) / 65536.0);
    }
  }
  return image;
}

MeshData heightFieldMesh(const HeightImage& image, bool smooth, double waterLevel) {
  MeshData m;
  const int w = image.width, h = image.height;
  if (w < 2 || h < 2) return m;
  // The image's top row lies at z = 1 and its bottom row at z = 0, its first column at x = 0.
  const auto height = [&](int x, int z) {
    return image.heights[size_t(h - 1 - std::clamp(z, 0, h - 1)) * size_t(w) + size_t(std::clamp(x, 0, w - 1))];
  };
  const double dx = 1.0 / (w - 1), dz = 1.0 / (h - 1);
  for (int z = 0; z < h; ++z) {
    for (int x = 0; x < w; ++x) {
      m.vertices.push_back({x * dx, height(x, z), z * dz});
      if (!smooth) continue;
      // The slope from the neighbouring heights, one-sided at the edges.
      const double sx = (height(x + 1, z) - height(x - 1, z)) / ((std::min(x + 1, w - 1) - std::max(x - 1, 0)) * dx);
      const double sz = (height(x, z + 1) - height(x, z - 1)) / ((std::min(z + 1, h - 1) - std::max(z - 1, 0)) * dz);
      m.normals.push_back(glm::normalize(glm::dvec3(-sx, 1, -sz)));
    }
  }
  // Each square split along the diagonal from its corner (x + 1, z) to (x, z + 1), as POV-Ray's trace() shows.
  const auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
    if (std::max({m.vertices[a].y, m.vertices[b].y, m.vertices[c].y}) < waterLevel) return;
    MeshData::Face f;
    f.v = {a, b, c};
    if (smooth) f.n = {int32_t(a), int32_t(b), int32_t(c)};
    m.faces.push_back(f);
  };
  for (int z = 0; z + 1 < h; ++z) {
    for (int x = 0; x + 1 < w; ++x) {
      const uint32_t p = uint32_t(z * w + x);
      add(p, p + 1, p + uint32_t(w));
      add(p + 1, p + uint32_t(w) + 1, p + uint32_t(w));
    }
  }
  if (waterLevel > 0) m.waterLevel = waterLevel;
  m.insideVector = glm::dvec3(0, 1, 0);  // below the surface is inside
  return m;
}

}  // namespace rt
