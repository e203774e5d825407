// The irradiance cache of a whole picture (--gi-cache), made the same whatever the threads, tiles or region:
// passes over the picture at halving pixel strides, each reading the cache as the passes before left it and
// appending its new records in pixel order afterwards (docs/gi.md).
#pragma once

#include "raytrace/accel/scene.hpp"
#include "raytrace/render/camera.hpp"
#include "raytrace/render/irradiance_cache.hpp"
#include "raytrace/render/options.hpp"
#include "raytrace/render/ray_counts.hpp"
#include "raytrace/util/progress.hpp"

namespace rt {

// The stride of the first pass, in pixels; the last is 1.
constexpr int kFirstCacheStride = 32;

// The cache of the camera's whole picture under options.gi.cache (its accuracy), made on options.threads
// threads. The rays it traces are added to `counts` and its pixels to `progress`, when given: each pixel of the
// picture once, in the pass of the coarsest stride that holds it.
template <class T>
IrradianceCache<T> prepareIrradianceCache(const Scene<T>& scene, const Camera<T>& camera, const RenderOptions& options,
                                          RayCounts* counts = nullptr, ProgressMeter* progress = nullptr);

}  // namespace rt
