// POV-Ray 3.7's `global_settings { radiosity { … } }` as written, with the manual's defaults (POV-Ray 3.7
// manual, "Global Settings" and "Radiosity"). The renderer draws it with the -gi gathering and its irradiance
// cache (render/radiosity.hpp, docs/gi.md "POV-Ray's radiosity").
#pragma once

namespace rt {

struct RadiosityDesc {
  double adcBailout = 0.01;
  bool alwaysSample = false;
  double brightness = 1;     // gathered light is multiplied by it at every level
  int count = 35;            // rays per new sample
  int countPool = 0;         // count's optional second value: the directions drawn from (0: count's own)
  double errorBound = 1.8;
  double grayThreshold = 0;  // 0: the gathered hue as is, 1: its gray
  double lowErrorFactor = 0.5;
  double maxSample = -1;     // non-positive: no limit on a sample's brightness
  double maximumReuse = 0.2, minimumReuse = 0.015;
  int nearestCount = 5;
  int nearestCountPretrace = 0;  // nearest_count's optional second value (0: not given)
  bool normal = false, media = false, subsurface = false;
  double pretraceStart = 0.08, pretraceEnd = 0.04;
  int recursionLimit = 2;   // levels of gathering: the last level's hits gather nothing
};

}  // namespace rt
