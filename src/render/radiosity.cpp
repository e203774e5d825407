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
  // POV-Ray reuses samples at every level; our cache serves the first only, so the levels below gather few
  // rays each (unbiased, their noise averaged by the level above). At least 64 rays a record: fewer leave the
  // records' noise as blotches that move block means; at most 256, which the chart shows is where more stops
  // paying (docs/gi.md).
  options.gi.samples = {std::clamp(r.count, 64, 256), 16};
  options.gi.bounces = r.recursionLimit;
  // error_bound is POV-Ray's allowed error; Ward's accuracy a is of the same kind at about a tenth of it
  // (1.8, the default, → 0.18), kept within the range the chart measured (0.1 to 0.3).
  options.gi.cache = float(std::clamp(r.errorBound / 10, 0.1, 0.3));
}

}  // namespace rt
