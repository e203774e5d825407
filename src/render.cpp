#include "raytrace/render.hpp"

#include <algorithm>

#include "raytrace/parallel.hpp"
#include "raytrace/progress.hpp"
#include "raytrace/tracer.hpp"

namespace rt {

namespace {

// Square tiles handed out to the threads: small enough to balance the load near the end of a render, large
// enough that handing them out costs nothing.
constexpr int kTile = 32;

}  // namespace

Image render(const SceneDesc& desc, int width, int height, const RenderOptions& options) {
  const Arithmetic arithmetic = chooseArithmetic(desc, options.arithmetic);
  Image image(width, height);
  withPrecision(arithmetic.precision, [&](auto tag) {
    using T = decltype(tag);
    const Scene<T> scene(desc, arithmetic, options.hierarchy, options.threads);
    const Camera<T> camera(desc.camera, width, height);
    const Tracer<T> tracer(scene, options);
    // Every pixel is computed on its own from constant state (the tracers' shadow caches change the order of
    // tests, never an answer), so the image is the same for any thread count. One tracer per tile: a tile's
    // shadow rays are coherent, and its cache is its own.
    const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
    ProgressMeter progress(options.progress, int64_t(width) * height, options.samples * options.samples);
    parallelFor(tilesX * tilesY, options.threads, [&](int tile) {
      const int x0 = tile % tilesX * kTile, y0 = tile / tilesX * kTile;
      const int x1 = std::min(width, x0 + kTile), y1 = std::min(height, y0 + kTile);
      Tracer<T> tileTracer = tracer;
      for (int y = y0; y < y1; ++y) tileTracer.block(camera, x0, y, x1, y + 1, image);
      progress.add(int64_t(x1 - x0) * (y1 - y0));
    });
  });
  return image;
}

}  // namespace rt
