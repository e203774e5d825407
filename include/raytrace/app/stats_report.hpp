// What --stats reports after a render: as two or three lines of text, or (--stats=json) as one JSON object.
#pragma once

#include <cstdint>
#include <string>

#include "raytrace/render/ray_counts.hpp"

namespace rt {

// A render's figures: its size and settings, how long each step took (seconds) and what it traced.
struct RenderStats {
  int width = 0, height = 0;
  double eyeRays = 1;  // per pixel: the samples' grid, or the mean where it varies (--aa, focal blur)
  int threads = 1;
  bool cache = false;  // --gi-cache: the cache's figures are reported too
  double load = 0, build = 0, trace = 0, write = 0;
  RayCounts rays;
  uint64_t peakMemory = 0;  // bytes, the most the process held at once
};

// "raytrace: load 1.2 ms, build …" lines, each ending in '\n'.
std::string statsText(const RenderStats& stats);

// One JSON object with the same figures (times in milliseconds, rounded as the text rounds them) and the peak
// memory, on one line ending in '\n'.
std::string statsJson(const RenderStats& stats);

}  // namespace rt
