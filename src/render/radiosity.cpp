#include "raytrace/render/radiosity.hpp"

#include <algorithm>

namespace rt {

void useRadiosity(RenderOptions& options, const SceneDesc& scene) {
  if (!scene.radiosity) return;
  const RadiosityDesc& r = *scene.radiosity;
  options.gi.radiosity = true;
  options.gi.brightness = float(r.brightness);
  options.gi.grayThreshold = float(std::clamp(r.grayThreshold, 0.0, 1.0));
  if (options.gi.enabled) return;
  options.gi.enabled = true;
  // POV-Ray reuses samples at every level; our cache serves the first only, so each level below gathers one
  // ray (unbiased, its noise averaged by the record's rays above: cornell.pov is 0.77/255 off POV-Ray in block
  // means in 16 s, and with 16 rays a level did not finish in 5 minutes). At least 64 rays a record: fewer
  // leave the records' noise as blotches that move block means; at most 256, where the chart shows more stops
  // paying (docs/gi.md).
  options.gi.samples = {std::clamp(r.count, 64, 256), 1};
  // At most -gi_bounces' 16 levels: a 17th adds a^16 of the light (a ≤ 1 the albedo), and each level keeps
  // buffers of its own.
  options.gi.bounces = std::min(r.recursionLimit, 16);
  // error_bound is Ward's accuracy on the distance to the nearest hit (manual, "error_bound"); the cache's
  // radius is the harmonic mean distance, about twice as long, so a = error_bound / 2, kept within the range the
  // chart measured (0.1 to 0.3).
  options.gi.cache = float(std::clamp(r.errorBound / 2, 0.1, 0.3));
}

}  // namespace rt
