// Rectangles of an image's pixels: what a tile of a render covers.
#pragma once

namespace rt {

// Columns [x0, x1) and rows [y0, y1), rows counted from the top as image files store them (OpenEXR's and
// pbrt's convention; the course counts pixel y upward, Image::at).
struct Region {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  bool operator==(const Region& o) const { return x0 == o.x0 && y0 == o.y0 && x1 == o.x1 && y1 == o.y1; }
};

inline Region wholeImage(int width, int height) { return {0, 0, width, height}; }

// The i-th of n bands of whole rows, 0 ≤ i < n ≤ height: rows [⌊i·height/n⌋, ⌊(i+1)·height/n⌋), so that the
// bands cover the image once and differ by at most a row.
inline Region rowBand(int i, int n, int width, int height) {
  const auto row = [&](int k) { return int(static_cast<long long>(k) * height / n); };
  return {0, row(i), width, row(i + 1)};
}

}  // namespace rt
