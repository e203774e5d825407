// Whole-image rendering: what `render` (and a .cli `write`) produces.
#pragma once

#include <ostream>

#include "raytrace/image/image.hpp"
#include "raytrace/image/region.hpp"
#include "raytrace/render/options.hpp"
#include "raytrace/render/ray_counts.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

// How long a render's steps took, in seconds (--stats); a file that writes several images adds them up.
struct RenderTimes {
  double build = 0;  // the scene's objects and their hierarchy
  double trace = 0;  // the pixels
};

// Sees the pixels as they are computed (--display, --preview): the colours of pixels x0 … x1 − 1 of the
// picture's row y (counted upward, as Image::at counts). Called on the render's threads, several at once.
class PixelObserver {
 public:
  virtual ~PixelObserver() = default;
  virtual void row(int x0, int y, int x1, const Color* colors) = 0;
};

// How a render is watched, apart from what it computes: nothing here changes a pixel.
struct RenderMonitor {
  std::ostream* progress = nullptr;  // where render() shows its progress line, if anywhere
  RenderTimes* times = nullptr;      // where render() adds how long it took, if anywhere
  RayCounts* rays = nullptr;         // where render() adds the rays it traced, if anywhere
  PixelObserver* pixels = nullptr;   // what sees each row of pixels as soon as it is computed, if anything
};

// Renders the scene at width × height.
Image render(const SceneDesc& scene, int width, int height, const RenderOptions& options,
             const RenderMonitor& monitor = {});
// Renders only the region of that picture: the same colours as those pixels of the whole render, bit for bit.
Image render(const SceneDesc& scene, int width, int height, const Region& region, const RenderOptions& options,
             const RenderMonitor& monitor = {});
// The same straight to the 8 bits a PNG holds, each channel converted by toByte() with the scene's convention.
Rgb8Image renderRgb8(const SceneDesc& scene, int width, int height, const RenderOptions& options,
                     const RenderMonitor& monitor = {});

}  // namespace rt
