#include "raytrace/app/live_picture.hpp"

#include <algorithm>

#include <glm/gtc/type_ptr.hpp>

namespace rt {

LivePicture::LivePicture(int height, const Region& region, Dialect::ToByte mode)
    : bottom_(height - region.y1), left_(region.x0), mode_(mode), colors_(region.width(), region.height()),
      bytes_(region.width(), region.height()) {
  // The colours start black; the bytes start unset.
  unsigned char* top = bytes_.at(0, bytes_.height() - 1);
  std::fill(top, top + size_t(bytes_.width()) * size_t(bytes_.height()) * 3, 0);
}

void LivePicture::row(int x0, int y, int x1, const Color* colors) {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::copy(colors, colors + (x1 - x0), &colors_.at(x0 - left_, y - bottom_));
  toBytes(glm::value_ptr(*colors), size_t(x1 - x0) * 3, bytes_.at(x0 - left_, y - bottom_), mode_);
  ++rows_;
}

uint64_t LivePicture::rowsSeen() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return rows_;
}

Image LivePicture::colors() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  Image copy(colors_.width(), colors_.height());
  std::copy(colors_.data(), colors_.data() + size_t(colors_.width()) * size_t(colors_.height()), copy.data());
  return copy;
}

Rgb8Image LivePicture::bytes() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  Rgb8Image copy(bytes_.width(), bytes_.height());
  std::copy(bytes_.data(), bytes_.data() + size_t(bytes_.width()) * size_t(bytes_.height()) * 3,
            copy.at(0, copy.height() - 1));
  return copy;
}

}  // namespace rt
