#include "raytrace/surface/image_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>

#include <stb/stb_image.h>

#include "raytrace/util/limits.hpp"
#include "raytrace/util/palette_image.hpp"

namespace rt {

namespace {

constexpr double kPi = 3.14159265358979323846;

double srgbDecoded(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

double wrapped(double x) { return x - std::floor(x); }

}  // namespace

ImageMap readImageFile(const std::string& path, double fileGamma, double workingGamma, const SourceLoc& at,
                       const std::vector<PaletteChannel>& paletteChannels) {
  const std::string what = "the image map \"" + path + "\"";
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(at, "cannot read " + what);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = int(std::min<size_t>(bytes.size(), size_t(INT32_MAX)));
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(data, size, &w, &h, &channels)) {
    throw ParseError(at, "cannot read " + what + ": " + stbi_failure_reason());
  }
  if (w <= 0 || h <= 0) throw ParseError(at, what + " has no pixels");
  // The decoded pixels (four floats each at most) and the map's colours are held at once.
  const std::uint64_t needed = std::uint64_t(w) * std::uint64_t(h) * (16 + sizeof(Rgbft));
  const std::string shortage = memoryShortage(what, needed, availableMemory());
  if (!shortage.empty()) throw ParseError(at, shortage);
  const bool hdr = stbi_is_hdr_from_memory(data, size);
  const bool alpha = channels == 2 || channels == 4;
  ImageMap image;
  image.width = w;
  image.height = h;
  image.pixels.resize(size_t(w) * size_t(h));
  const double toWorking = workingGamma > 0 ? 1 / workingGamma : 1;
  const auto decoded = [&](double v) {
    const double linear = hdr || fileGamma < 0 ? v : fileGamma > 0 ? std::pow(v, fileGamma) : srgbDecoded(v);
    return float(toWorking == 1 ? linear : std::pow(linear, toWorking));
  };
  if (hdr) {
    float* pixels = stbi_loadf_from_memory(data, size, &w, &h, &channels, 4);
    if (!pixels) throw ParseError(at, "cannot read " + what + ": " + stbi_failure_reason());
    for (size_t i = 0; i < image.pixels.size(); ++i) {
      const float* p = pixels + 4 * i;
      image.pixels[i] = {Color(decoded(p[0]), decoded(p[1]), decoded(p[2])), 0, alpha ? 1 - p[3] : 0};
    }
    stbi_image_free(pixels);
    return image;
  }
  stbi_us* pixels = stbi_load_16_from_memory(data, size, &w, &h, &channels, 4);
  if (!pixels) throw ParseError(at, "cannot read " + what + ": " + stbi_failure_reason());
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const stbi_us* p = pixels + 4 * i;
    image.pixels[i] = {Color(decoded(p[0] / 65535.0), decoded(p[1] / 65535.0), decoded(p[2] / 65535.0)), 0,
                       alpha ? float(1 - p[3] / 65535.0) : 0};
  }
  stbi_image_free(pixels);
  const std::optional<PaletteImage> palette = paletteChannels.empty() ? std::nullopt : paletteIndices(bytes);
  if (palette && palette->indices.size() == image.pixels.size()) {
    for (const PaletteChannel& c : paletteChannels) {
      for (size_t i = 0; i < image.pixels.size(); ++i) {
        if (palette->indices[i] == c.index) (c.transmit ? image.pixels[i].transmit : image.pixels[i].filter) = c.amount;
      }
    }
  }
  return image;
}

const Rgbft* imageExtremes(const ImageMap& image) { return image.extremes; }

void ImageMap::findExtremes() {
  Rgbft& lo = extremes[0];
  Rgbft& hi = extremes[1];
  lo = hi = pixels.front();
  for (const Rgbft& c : pixels) {
    lo = {glm::min(lo.rgb, c.rgb), std::min(lo.filter, c.filter), std::min(lo.transmit, c.transmit)};
    hi = {glm::max(hi.rgb, c.rgb), std::max(hi.filter, c.filter), std::max(hi.transmit, c.transmit)};
  }
  // Outside a map drawn once the pigment is clear.
  if (once) lo.rgb = glm::min(lo.rgb, Color(0)), hi.transmit = 1;
}

// The image's (u, v) at p, as POV-Ray 3.7 lays it (measured): planar takes x and y; the others go once round
// the y axis, u = 0.75 facing -z and growing towards +x, v from the latitude (sphere), from y (cylinder) or
// once round the tube of the torus of major radius 1 (torus: 0.5 on its outer equator, rising over its top).
Rgbft ImageMap::at(const glm::dvec3& p) const {
  double u = p.x, v = p.y;
  if (mapping != Mapping::Planar) {
    u = std::atan2(p.z, p.x) / (2 * kPi);
    if (mapping == Mapping::Spherical) {
      const double length = glm::length(p);
      v = length > 0 ? std::asin(std::clamp(p.y / length, -1.0, 1.0)) / kPi + 0.5 : 0.5;
    }
    if (mapping == Mapping::Torus) v = std::atan2(p.y, std::hypot(p.x, p.z) - 1) / (2 * kPi) + 0.5;
  }
  if (once && (v < 0 || v >= 1 || (mapping == Mapping::Planar && (u < 0 || u >= 1)))) {
    return {Color(0), 0, 1};
  }
  u = wrapped(u) * width;
  v = wrapped(v) * height;
  const auto pixel = [&](long x, long y) -> const Rgbft& {
    x = (x % width + width) % width;
    y = (y % height + height) % height;
    return pixels[size_t(height - 1 - y) * size_t(width) + size_t(x)];
  };
  if (interpolation == Interpolation::None) return pixel(long(u), long(v));
  // Between the four pixels whose centres surround p, wrapping round the image's edges.
  const double fx = u - 0.5, fy = v - 0.5;
  const long x0 = long(std::floor(fx)), y0 = long(std::floor(fy));
  const double tx = fx - double(x0), ty = fy - double(y0);
  const Rgbft* corner[4] = {&pixel(x0, y0), &pixel(x0 + 1, y0), &pixel(x0, y0 + 1), &pixel(x0 + 1, y0 + 1)};
  double weight[4];
  if (interpolation == Interpolation::Bilinear) {
    weight[0] = (1 - tx) * (1 - ty), weight[1] = tx * (1 - ty), weight[2] = (1 - tx) * ty, weight[3] = tx * ty;
  } else {
    // Normalized distance: each pixel weighted by the inverse square of its distance (measured against
    // POV-Ray 3.7's renders); a pixel's own centre gives its colour.
    const double dx[4] = {tx, 1 - tx, tx, 1 - tx}, dy[4] = {ty, ty, 1 - ty, 1 - ty};
    for (int i = 0; i < 4; ++i) {
      const double d2 = dx[i] * dx[i] + dy[i] * dy[i];
      if (d2 == 0) return *corner[i];
      weight[i] = 1 / d2;
    }
  }
  const double total = weight[0] + weight[1] + weight[2] + weight[3];
  Rgbft sum{Color(0), 0, 0};
  for (int i = 0; i < 4; ++i) {
    const float k = float(weight[i] / total);
    sum = {sum.rgb + k * corner[i]->rgb, sum.filter + k * corner[i]->filter, sum.transmit + k * corner[i]->transmit};
  }
  return sum;
}

}  // namespace rt
