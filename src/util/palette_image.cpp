#include "raytrace/util/palette_image.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>

#include <stb/stb_image.h>

namespace rt {

namespace {

uint32_t bigEndian(const unsigned char* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

// A palette PNG's indices: the chunks unpacked here, the compressed rows inflated by stb_image, and the rows'
// filters undone as the PNG specification (§9) says. Nothing for any other PNG, or an interlaced one.
std::optional<PaletteImage> pngIndices(const std::string& bytes) {
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  if (bytes.size() < 33 || std::memcmp(b, "\x89PNG\r\n\x1a\n", 8) != 0) return std::nullopt;
  const uint32_t width = bigEndian(b + 16), height = bigEndian(b + 20);
  const int depth = b[24], colourType = b[25], interlace = b[28];
  if (colourType != 3 || interlace != 0 || width == 0 || height == 0 || width > 65536 || height > 65536) {
    return std::nullopt;
  }
  std::string compressed;
  for (size_t at = 8; at + 12 <= bytes.size();) {
    const size_t length = bigEndian(b + at);
    if (at + 12 + length > bytes.size()) return std::nullopt;
    if (std::memcmp(b + at + 4, "IDAT", 4) == 0) compressed.append(bytes, at + 8, length);
    at += 12 + length;
  }
  const size_t stride = (size_t(width) * size_t(depth) + 7) / 8;
  int size = 0;
  char* raw = stbi_zlib_decode_malloc(compressed.data(), int(compressed.size()), &size);
  if (!raw) return std::nullopt;
  const std::string rows(raw, size_t(size));
  stbi_image_free(raw);
  if (rows.size() < (stride + 1) * height) return std::nullopt;
  PaletteImage image{int(width), int(height), {}};
  image.indices.reserve(size_t(width) * height);
  std::vector<unsigned char> line(stride), previous(stride, 0);
  const size_t bpp = 1;  // a palette pixel's bytes, for the filters, rounded up to one
  for (uint32_t y = 0; y < height; ++y) {
    const auto* in = reinterpret_cast<const unsigned char*>(rows.data()) + y * (stride + 1);
    const int filter = in[0];
    for (size_t i = 0; i < stride; ++i) {
      const int a = i >= bpp ? line[i - bpp] : 0, up = previous[i], c = i >= bpp ? previous[i - bpp] : 0;
      int predicted = 0;
      if (filter == 1) predicted = a;
      else if (filter == 2) predicted = up;
      else if (filter == 3) predicted = (a + up) / 2;
      else if (filter == 4) {
        const int p = a + up - c, pa = std::abs(p - a), pb = std::abs(p - up), pc = std::abs(p - c);
        predicted = pa <= pb && pa <= pc ? a : (pb <= pc ? up : c);
      }
      line[i] = static_cast<unsigned char>(in[1 + i] + predicted);
    }
    for (uint32_t x = 0; x < width; ++x) {
      const size_t bit = size_t(x) * size_t(depth);
      const int index = (line[bit / 8] >> (8 - depth - int(bit % 8))) & ((1 << depth) - 1);
      image.indices.push_back(index);
    }
    previous = line;
  }
  return image;
}

// A GIF's first image as palette indices, over 256 as a PNG's (stb_image gives only the colours): the blocks
// walked and the LZW codes expanded as the GIF 89a specification (§20–§22, appendix F) says. Nothing for any
// other file.
std::optional<PaletteImage> gifIndices(const std::string& bytes) {
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
  const size_t n = bytes.size();
  if (n < 13 || (std::memcmp(b, "GIF87a", 6) != 0 && std::memcmp(b, "GIF89a", 6) != 0)) return std::nullopt;
  size_t at = 13;
  if (b[10] & 0x80) at += 3u << ((b[10] & 7) + 1);  // the global colour table
  while (at < n && b[at] == 0x21) {                  // extensions, each a label and data sub-blocks
    at += 2;
    while (at < n && b[at] != 0) at += size_t(b[at]) + 1;
    ++at;
  }
  if (at + 10 > n || b[at] != 0x2c) return std::nullopt;
  const int width = b[at + 5] | b[at + 6] << 8, height = b[at + 7] | b[at + 8] << 8;
  const bool interlaced = b[at + 9] & 0x40;
  if (b[at + 9] & 0x80) at += 3u << ((b[at + 9] & 7) + 1);  // a local colour table
  at += 10;
  if (at >= n || width == 0 || height == 0) return std::nullopt;
  const int minimum = b[at++];
  if (minimum < 2 || minimum > 11) return std::nullopt;
  std::vector<unsigned char> data;
  while (at < n && b[at] != 0) {
    const size_t length = b[at];
    if (at + 1 + length > n) return std::nullopt;
    data.insert(data.end(), b + at + 1, b + at + 1 + length);
    at += length + 1;
  }
  // The LZW table: each code's previous code and last byte; the clear code resets it.
  const int clear = 1 << minimum, end = clear + 1;
  std::vector<int> prefix(4096, -1);
  std::vector<unsigned char> suffix(4096), first(4096), stack;
  for (int c = 0; c < clear; ++c) suffix[size_t(c)] = first[size_t(c)] = static_cast<unsigned char>(c);
  std::vector<unsigned char> indices;
  const size_t pixels = size_t(width) * size_t(height);
  int size = minimum + 1, next = end + 1, previous = -1;
  size_t bit = 0;
  while (indices.size() < pixels && bit + size_t(size) <= data.size() * 8) {
    int code = 0;
    for (int k = 0; k < size; ++k, ++bit) code |= ((data[bit / 8] >> (bit % 8)) & 1) << k;
    if (code == clear) {
      size = minimum + 1;
      next = end + 1;
      previous = -1;
      continue;
    }
    if (code == end) break;
    if (code > next || (code == next && previous < 0)) return std::nullopt;
    const int expand = code == next ? previous : code;
    stack.clear();
    for (int c = expand; c >= 0; c = prefix[size_t(c)]) stack.push_back(suffix[size_t(c)]);
    if (code == next) stack.insert(stack.begin(), first[size_t(previous)]);
    indices.insert(indices.end(), stack.rbegin(), stack.rend());
    if (previous >= 0 && next < 4096) {
      prefix[size_t(next)] = previous;
      suffix[size_t(next)] = first[size_t(expand)];
      first[size_t(next)] = first[size_t(previous)];
      if (++next == 1 << size && size < 12) ++size;
    }
    previous = code;
  }
  if (indices.size() < pixels) return std::nullopt;
  PaletteImage image{width, height, std::vector<int>(pixels)};
  // An interlaced image's rows come in four passes: every 8th from 0, every 8th from 4, every 4th from 2, every
  // 2nd from 1.
  int row = 0;
  for (int y = 0; y < height; ++y) {
    int target = y;
    if (interlaced) {
      static constexpr int kStart[] = {0, 4, 2, 1}, kStep[] = {8, 8, 4, 2};
      int pass = 0, k = y;
      while (pass < 4 && k >= (height - kStart[pass] + kStep[pass] - 1) / kStep[pass]) {
        k -= (height - kStart[pass] + kStep[pass] - 1) / kStep[pass];
        ++pass;
      }
      target = kStart[pass] + k * kStep[pass];
    }
    for (int x = 0; x < width; ++x) {
      image.indices[size_t(target) * size_t(width) + size_t(x)] = indices[size_t(row) * size_t(width) + size_t(x)];
    }
    ++row;
  }
  return image;
}

}  // namespace

std::optional<PaletteImage> paletteIndices(const std::string& bytes) {
  if (std::optional<PaletteImage> png = pngIndices(bytes)) return png;
  return gifIndices(bytes);
}

}  // namespace rt
