// The picture so far, as a render computes it: what --display shows and --preview writes.
#pragma once

#include <cstdint>
#include <mutex>

#include "raytrace/image/image.hpp"
#include "raytrace/image/region.hpp"
#include "raytrace/render/renderer.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

// The region of a width × height picture, black until its rows arrive, kept both as colours and as the bytes
// a PNG would hold (converted with the scene's convention), so that a window shows what the file will.
class LivePicture : public PixelObserver {
 public:
  LivePicture(int height, const Region& region, Dialect::ToByte mode);

  void row(int x0, int y, int x1, const Color* colors) override;

  int width() const { return colors_.width(); }
  int height() const { return colors_.height(); }
  // How many rows have arrived: a reader compares it with the count it last saw.
  uint64_t rowsSeen() const;
  // Copies of the picture so far.
  Image colors() const;
  Rgb8Image bytes() const;

 private:
  int bottom_;  // the picture's row (counted upward) of the region's bottom row
  int left_;
  Dialect::ToByte mode_;
  mutable std::mutex mutex_;
  Image colors_;
  Rgb8Image bytes_;
  uint64_t rows_ = 0;
};

}  // namespace rt
