// bump_map: a normal bent by an image's heights, the grey 0.297·r + 0.589·g + 0.114·b of its pixels (POV-Ray 3.7
// manual, "Bump Map"). The bend is that of the plane through three heights: at the point, and one pixel down
// and to either side of it, each read as the image map reads a colour (so with its interpolation); it is
// counted per pixel, so that neither the image's size nor the normal's scale changes the bumps' depth. With
// `once` the normal is bent only over the image, whose heights are still read as if it were repeated.
// Measured on POV-Ray's renders, tests/surface/patterns/test_bump_map.cpp.
#include "raytrace/surface/image_map.hpp"
#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class BumpMap final : public Pattern {
 public:
  BumpMap(std::shared_ptr<const ImageMap> image, bool once)
      : image_(std::move(image)), du_(1.0 / image_->width), dv_(1.0 / image_->height), once_(once) {}
  double value(const glm::dvec3& p) const override {
    const Color c = image_->at(p).rgb;
    return 0.297 * double(c.r) + 0.589 * double(c.g) + 0.114 * double(c.b);
  }
  bool hasBump() const override { return true; }
  // The plane through (0, 0, h0), (−1, −1, h1) and (1, −1, h2), in pixels, has the normal
  // ((h1 − h2) / 2, (h1 + h2) / 2 − h0, 1); the normal is bent by the first two against the surface's.
  glm::dvec3 bump(const glm::dvec3& p) const override {
    if (once_ && (p.x < 0 || p.x >= 1 || p.y < 0 || p.y >= 1)) return glm::dvec3(0);
    const double h0 = value(p);
    const double h1 = value(p + glm::dvec3(-du_, -dv_, 0));
    const double h2 = value(p + glm::dvec3(du_, -dv_, 0));
    return {(h2 - h1) / 2, h0 - (h1 + h2) / 2, 0};
  }

 private:
  std::shared_ptr<const ImageMap> image_;
  double du_, dv_;
  bool once_;
};

}  // namespace

std::unique_ptr<Pattern> makeBumpMap(const ImageMap& image) {
  auto repeated = std::make_shared<ImageMap>(image);
  repeated->once = false;
  return std::make_unique<BumpMap>(std::move(repeated), image.once);
}

}  // namespace rt
