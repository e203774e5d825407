#include "raytrace/render/renderer.hpp"

#include <algorithm>
#include <mutex>

#include <glm/gtc/type_ptr.hpp>

#include "raytrace/util/parallel.hpp"
#include "raytrace/util/progress.hpp"
#include "raytrace/util/stopwatch.hpp"
#include "raytrace/render/tracer.hpp"

namespace rt {

namespace {

// Square tiles handed out to the threads: small enough to balance the load near the end of a render, large
// enough that handing them out costs nothing.
constexpr int kTile = 32;

// Renders the scene tile by tile on the threads and hands each finished row of a tile to
// store(x0, y, x1, colours): the colours of pixels x0 … x1 − 1 of row y.
template <class Store>
void renderRows(const SceneDesc& desc, int width, int height, const RenderOptions& options,
                const RenderMonitor& monitor, const Store& store) {
  const Arithmetic arithmetic =
      chooseArithmetic(desc, options.arithmetic, View{width * options.samples, height * options.samples});
  withPrecision(arithmetic.tier, [&](auto tag) {
    using T = decltype(tag);
    Stopwatch watch;
    const Scene<T> scene(desc, arithmetic, options.hierarchy, options.threads);
    const Camera<T> camera(desc.camera, width, height);
    const Tracer<T> tracer(scene, options);
    const double build = watch.lap();
    // Every pixel is computed on its own from constant state (the tracers' shadow caches change the order of
    // tests, never an answer), so the image is the same for any thread count. One tracer per tile: a tile's
    // shadow rays are coherent, and its cache is its own. Tiles go column by column, so that threads work on
    // tiles one above another, whose rows lie on pages of their own: side by side, they would take the same
    // fresh pages of the image at once, and the kernel would fault each twice (docs/performance-notes.md,
    // "Tile order").
    const int tilesX = (width + kTile - 1) / kTile, tilesY = (height + kTile - 1) / kTile;
    std::mutex countsMutex;
    ProgressMeter progress(monitor.progress, int64_t(width) * height, options.samples * options.samples);
    parallelFor(tilesX * tilesY, options.threads, [&](int tile) {
      const int x0 = tile / tilesY * kTile, y0 = tile % tilesY * kTile;
      const int x1 = std::min(width, x0 + kTile), y1 = std::min(height, y0 + kTile);
      Tracer<T> tileTracer = tracer;
      for (int y = y0; y < y1; ++y) {
        store(x0, y, x1, tileTracer.tile(camera, x0, y, x1, y + 1));
        progress.add(x1 - x0);  // row by row: a -gi tile takes seconds
      }
      if (monitor.rays) {
        const std::lock_guard<std::mutex> lock(countsMutex);
        *monitor.rays += tileTracer.counts();
      }
    });
    if (monitor.times) {
      monitor.times->build += build;
      monitor.times->trace += watch.lap();
    }
  });
}

}  // namespace

Image render(const SceneDesc& desc, int width, int height, const RenderOptions& options,
             const RenderMonitor& monitor) {
  Image image(width, height);
  renderRows(desc, width, height, options, monitor, [&](int x0, int y, int x1, const Color* colors) {
    std::copy(colors, colors + (x1 - x0), &image.at(x0, y));
  });
  return image;
}

Rgb8Image renderRgb8(const SceneDesc& desc, int width, int height, const RenderOptions& options,
                     const RenderMonitor& monitor) {
  Rgb8Image image(width, height);
  const Conventions::ToByte mode = desc.conventions.toByte;
  renderRows(desc, width, height, options, monitor, [&](int x0, int y, int x1, const Color* colors) {
    toBytes(glm::value_ptr(*colors), size_t(x1 - x0) * 3, image.at(x0, y), mode);
  });
  return image;
}

}  // namespace rt
