#include "raytrace/render/renderer.hpp"

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <optional>
#include <type_traits>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "raytrace/util/error.hpp"
#include "raytrace/util/limits.hpp"
#include "raytrace/util/message.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/util/progress.hpp"
#include "raytrace/util/stopwatch.hpp"
#include "raytrace/render/antialias.hpp"
#include "raytrace/render/irradiance_prepass.hpp"
#include "raytrace/render/scene_setup.hpp"
#include "raytrace/render/tracer.hpp"

namespace rt {

namespace {

// Square tiles handed out to the threads: small enough to balance the load near the end of a render, large
// enough that handing them out costs nothing.
constexpr int kTile = 32;

// Renders the region of the scene's width × height picture tile by tile on the threads and hands each
// finished row of a tile to store(x0, y, x1, colours): the colours of pixels x0 … x1 − 1 of row y (counted
// upward, as Image::at counts).
template <class Store>
void renderRows(const SceneDesc& desc, int width, int height, const Region& region, const RenderOptions& requested,
                const RenderMonitor& monitor, const Store& store) {
  // Each thread's tracer keeps shadow rays for every light: a million lights take gigabytes. As many threads as
  // there is memory for (the image is the same on any number), and at least one; counted at double's size.
  const std::uint64_t perTracer = desc.lights.size() * Tracer<double>::bytesPerLight(requested);
  const std::uint64_t available = availableMemory();
  const std::string shortage =
      memoryShortage("rendering " + thousands(desc.lights.size()) + " lights", perTracer, available);
  if (!shortage.empty()) throw Error(shortage);
  RenderOptions options = requested;
  if (perTracer > 0) options.threads = int(std::min(std::uint64_t(options.threads), available / perTracer));
  Stopwatch watch;
  withScene(desc, width, height, options, [&](const auto& scene, const auto& camera) {
    using T = typename std::decay_t<decltype(scene)>::Real;
    Tracer<T> tracer(scene, options);
    const double build = watch.lap();
    // Every pixel is computed on its own from constant state (the tracers' shadow caches change the order of
    // tests, never an answer), so the image is the same for any thread count. One tracer per tile: a tile's
    // shadow rays are coherent, and its cache is its own. Tiles go column by column, so that threads work on
    // tiles one above another, whose rows lie on pages of their own: side by side, they would take the same
    // fresh pages of the image at once, and the kernel would fault each twice (docs/performance-notes.md,
    // "Tile order").
    // Every pixel's colour depends on its (x, y) alone, so a region's pixels are those of the whole picture.
    const int left = region.x0, bottom = height - region.y1, right = region.x1, top = height - region.y0;
    const int tilesX = (right - left + kTile - 1) / kTile, tilesY = (top - bottom + kTile - 1) / kTile;
    // --gi-cache: the whole picture's cache first, whatever the region (its passes trace each pixel once more).
    const bool caching = options.gi.enabled && options.gi.cache;
    ProgressMeter progress(monitor.progress,
                           int64_t(region.width()) * region.height() + (caching ? int64_t(width) * height : 0),
                           options.samples * options.samples);
    std::optional<IrradianceCache<T>> cache;
    if (caching) {
      cache = prepareIrradianceCache(scene, camera, options, monitor.rays, &progress);
      tracer.useCache(&*cache);
    }
    // --aa: the first rays of every pixel first, on the threads; then each tile's supersamples.
    RayCounts firstRays;
    std::optional<AdaptiveSampler<T>> adaptive;
    if (options.aa.method != 0) {
      adaptive.emplace(tracer, camera, options, width, height, left, bottom, right, top, firstRays);
    }
    if (monitor.rays) *monitor.rays += firstRays;
    std::mutex countsMutex;
    parallelFor(tilesX * tilesY, options.threads, [&](int tile) {
      const int x0 = left + tile / tilesY * kTile, y0 = bottom + tile % tilesY * kTile;
      const int x1 = std::min(right, x0 + kTile), y1 = std::min(top, y0 + kTile);
      Tracer<T> tileTracer = tracer;
      std::vector<Color> antialiased;
      if (adaptive) adaptive->tile(tileTracer, x0, y0, x1, y1, antialiased);
      for (int y = y0; y < y1; ++y) {
        const Color* colors = adaptive ? &antialiased[size_t(y - y0) * size_t(x1 - x0)]
                                       : tileTracer.tile(camera, x0, y, x1, y + 1);
        store(x0, y, x1, colors);
        if (monitor.pixels) monitor.pixels->row(x0, y, x1, colors);
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
  return render(desc, width, height, wholeImage(width, height), options, monitor);
}

Image render(const SceneDesc& desc, int width, int height, const Region& region, const RenderOptions& options,
             const RenderMonitor& monitor) {
  Image image(region.width(), region.height());
  // Row y of the picture, counted upward, is row y − (height − y1) of the region's image.
  const int bottom = height - region.y1;
  renderRows(desc, width, height, region, options, monitor, [&](int x0, int y, int x1, const Color* colors) {
    std::copy(colors, colors + (x1 - x0), &image.at(x0 - region.x0, y - bottom));
  });
  return image;
}

Rgb8Image renderRgb8(const SceneDesc& desc, int width, int height, const RenderOptions& options,
                     const RenderMonitor& monitor) {
  Rgb8Image image(width, height);
  const Dialect::ToByte mode = desc.dialect.toByte();
  renderRows(desc, width, height, wholeImage(width, height), options, monitor,
             [&](int x0, int y, int x1, const Color* colors) {
    toBytes(glm::value_ptr(*colors), size_t(x1 - x0) * 3, image.at(x0, y), mode);
  });
  return image;
}

}  // namespace rt
