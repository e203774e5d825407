#include <catch2/catch.hpp>

#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "raytrace/image/image.hpp"
#include "raytrace/image/png.hpp"

namespace {

uint32_t u32(const std::vector<unsigned char>& b, size_t at) {
  return uint32_t(b[at]) << 24 | uint32_t(b[at + 1]) << 16 | uint32_t(b[at + 2]) << 8 | b[at + 3];
}

// A minimal reader for what encodePng writes: checks every chunk CRC, inflates the IDAT data and undoes the
// "Up" filter.
std::vector<unsigned char> decode(const std::vector<unsigned char>& png, int& width, int& height) {
  REQUIRE(std::string(png.begin(), png.begin() + 8) == "\x89PNG\r\n\x1A\n");
  std::vector<unsigned char> idat;
  std::string last;
  for (size_t at = 8; at < png.size();) {
    const uint32_t size = u32(png, at);
    const std::string type(png.begin() + long(at) + 4, png.begin() + long(at) + 8);
    REQUIRE(u32(png, at + 8 + size) == crc32(0, png.data() + at + 4, size + 4));
    if (type == "IHDR") {
      width = int(u32(png, at + 8));
      height = int(u32(png, at + 12));
      CHECK(std::vector<unsigned char>(png.begin() + long(at) + 16, png.begin() + long(at) + 21) ==
            std::vector<unsigned char>{8, 2, 0, 0, 0});
    }
    if (type == "IDAT") idat.insert(idat.end(), png.begin() + long(at) + 8, png.begin() + long(at) + 8 + size);
    last = type;
    at += 12 + size;
  }
  CHECK(last == "IEND");
  const size_t stride = size_t(width) * 3;
  std::vector<unsigned char> raw((stride + 1) * size_t(height));
  uLongf rawSize = uLongf(raw.size());
  REQUIRE(uncompress(raw.data(), &rawSize, idat.data(), uLong(idat.size())) == Z_OK);
  REQUIRE(rawSize == raw.size());
  std::vector<unsigned char> rgb;
  for (int y = 0; y < height; ++y) {
    REQUIRE(raw[size_t(y) * (stride + 1)] == 2);
    for (size_t i = 0; i < stride; ++i) {
      const unsigned char above = y > 0 ? rgb[rgb.size() - stride] : 0;
      rgb.push_back(static_cast<unsigned char>(raw[size_t(y) * (stride + 1) + 1 + i] + above));
    }
  }
  return rgb;
}

}  // namespace

TEST_CASE("encodePng round-trips through zlib, in one segment and in many", "[png]") {
  for (const auto& [width, height] : {std::pair{1, 1}, {7, 3}, {640, 1000}}) {
    CAPTURE(width, height);
    std::mt19937 rng(unsigned(width * height));
    std::vector<unsigned char> rgb(size_t(width) * size_t(height) * 3);
    // Smooth rows with noise: compressible, but never trivially. The tallest image is noise alone below its
    // first 100 rows: deflate's worst case, stored blocks, must fit each segment's buffer.
    for (size_t i = 0; i < rgb.size(); ++i) {
      rgb[i] = static_cast<unsigned char>(height > 100 && i > size_t(width) * 300 ? rng() : i / 97 + rng() % 8);
    }
    const auto png = rt::encodePng(rgb.data(), width, height, 1);
    int w = 0, h = 0;
    CHECK(decode(png, w, h) == rgb);
    CHECK(w == width);
    CHECK(h == height);
    // The file depends on the pixels only.
    CHECK(rt::encodePng(rgb.data(), width, height, 2) == png);
    CHECK(rt::encodePng(rgb.data(), width, height, 5) == png);
  }
}

TEST_CASE("toByte rounds half up exactly as std::lround and truncates as a cast", "[png]") {
  for (int k = 0; k <= 255; ++k) {
    // Every float within 64 steps of each rounding boundary k + 0.5 (after the ×255).
    float c = (float(k) + 0.5f) / 255.0f;
    for (int i = 0; i < 64; ++i) c = std::nextafter(c, 0.0f);
    for (int i = 0; i < 128; ++i, c = std::nextafter(c, 2.0f)) {
      const float v = std::min(c, 1.0f) * 255.0f;
      CHECK(int(rt::toByte(c, rt::Conventions::ToByte::Round)) == std::lround(v));
      CHECK(int(rt::toByte(c, rt::Conventions::ToByte::Truncate)) == int(v));
    }
  }
}
