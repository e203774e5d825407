#include "raytrace/render/irradiance_prepass.hpp"

#include <cstdint>
#include <mutex>
#include <vector>

#include "raytrace/render/tracer.hpp"
#include "raytrace/util/error.hpp"
#include "raytrace/util/limits.hpp"
#include "raytrace/util/message.hpp"
#include "raytrace/util/parallel.hpp"

namespace rt {

template <class T>
IrradianceCache<T> prepareIrradianceCache(const Scene<T>& scene, const Camera<T>& camera, const RenderOptions& options,
                                          RayCounts* counts, ProgressMeter* progress) {
  IrradianceCache<T> cache(*options.gi.cache, camera.eye(), camera.pixelSize());
  const Tracer<T> prototype(scene, options);
  std::mutex countsMutex;
  uint64_t records = 0, traced = 0;  // so far, for the memory the next pass is likely to take
  for (int stride = kFirstCacheStride; stride >= 1; stride /= 2) {
    // Row by row: each row's records come from one tracer in pixel order, and the rows are appended in order.
    const int rows = (camera.height() + stride - 1) / stride;
    // The cache grows with pixels × samples; a pass is checked before it runs, at as many records per traced
    // pixel as the passes before made (twice: its rows, then the cache's copy).
    const uint64_t pixels = uint64_t(rows) * uint64_t((camera.width() + stride - 1) / stride);
    if (traced > 0) {
      const uint64_t expected = records * pixels / traced;
      const std::string shortage =
          memoryShortage("the irradiance cache, at some " + thousands(records + expected) + " records,",
                         (records + 2 * expected) * sizeof(IrradianceRecord<T>), availableMemory());
      if (!shortage.empty()) throw Error(shortage + " (a larger --gi-cache accuracy makes fewer)");
    }
    traced += pixels;
    std::vector<std::vector<IrradianceRecord<T>>> made(static_cast<size_t>(rows));
    parallelFor(rows, options.threads, [&](int row) {
      const int y = row * stride;
      // A pixel an earlier (coarser) pass traced is left out: every point it sees is covered already.
      const bool earlierRow = stride < kFirstCacheStride && y % (2 * stride) == 0;
      Tracer<T> tracer = prototype;
      tracer.useCache(&cache, &made[size_t(row)]);
      int pixels = 0;
      for (int x = 0; x < camera.width(); x += stride) {
        if (earlierRow && x % (2 * stride) == 0) continue;
        tracer.pixel(camera, x, y);
        ++pixels;
      }
      if (progress) progress->add(pixels);
      if (counts) {
        const std::lock_guard<std::mutex> lock(countsMutex);
        *counts += tracer.counts();
      }
    });
    std::vector<IrradianceRecord<T>> pass;
    for (const auto& row : made) pass.insert(pass.end(), row.begin(), row.end());
    records += pass.size();
    cache.add(pass);
  }
  return cache;
}

template IrradianceCache<float> prepareIrradianceCache(const Scene<float>&, const Camera<float>&,
                                                       const RenderOptions&, RayCounts*, ProgressMeter*);
template IrradianceCache<double> prepareIrradianceCache(const Scene<double>&, const Camera<double>&,
                                                        const RenderOptions&, RayCounts*, ProgressMeter*);

}  // namespace rt
