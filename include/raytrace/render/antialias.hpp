// POV-Ray's adaptive anti-aliasing (the manual, 3.2 "Anti-Aliasing Options"; --aa, docs/povray-command-line.md):
// +AM1 traces one ray per pixel and gives the pixels that differ from a neighbour R x R more rays; +AM2 traces the
// pixels' corners and subdivides a square whose corners differ, to R − 1 levels. Every ray and every decision
// depends only on pixel coordinates (jitter from sampler.hpp's counter-based numbers), so the picture is the
// same for any threads, tiles or region.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "raytrace/render/camera.hpp"
#include "raytrace/render/options.hpp"
#include "raytrace/render/ray_counts.hpp"
#include "raytrace/render/tracer.hpp"

namespace rt {

// A colour as anti-aliasing compares it: clipped to [0, 1] and raised to 1/2.5, POV-Ray's default
// Antialias_Gamma ("POV-Ray compares gamma-adjusted values").
Color aaCompared(const Color& c);
// The manual's difference of two compared colours: |r1 − r2| + |g1 − g2| + |b1 − b2|.
inline float aaDifference(const Color& a, const Color& b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}
// +AM1's choice for pixel (x, y) of a w × h grid of compared colours (row by row): a pixel that differs from
// its neighbour to the left, right, above or below by more than `threshold` is supersampled ("both pixels are
// super-sampled"). Inline: every pixel of the picture pays it.
inline bool refinedPixel(const Color* compared, int w, int h, int x, int y, float threshold) {
  const size_t p = size_t(y) * size_t(w) + size_t(x);
  const Color& c = compared[p];
  return (x > 0 && aaDifference(c, compared[p - 1]) > threshold) ||
         (x + 1 < w && aaDifference(c, compared[p + 1]) > threshold) ||
         (y > 0 && aaDifference(c, compared[p - size_t(w)]) > threshold) ||
         (y + 1 < h && aaDifference(c, compared[p + size_t(w)]) > threshold);
}

// The pixels [left, right) × [bottom, top) of a width × height picture (y counted upward), anti-aliased.
template <class T> class AdaptiveSampler {
 public:
  // Traces the rays every pixel starts from on options.threads threads, each with a copy of `tracer`: +AM1 each
  // pixel's own ray, over the area and the pixels around it; +AM2 the pixels' corners. Their rays are added
  // to `counts`.
  AdaptiveSampler(const Tracer<T>& tracer, const Camera<T>& camera, const RenderOptions& options, int width,
                  int height, int left, int bottom, int right, int top, RayCounts& counts);

  // The finished colours of pixels [x0, x1) × [y0, y1) of the area, row by row from y0, into `out`; the
  // supersamples are traced with `tracer` (a thread's own).
  void tile(Tracer<T>& tracer, int x0, int y0, int x1, int y1, std::vector<Color>& out) const;

 private:
  void nonRecursive(Tracer<T>& tracer, int x0, int y0, int x1, int y1, std::vector<Color>& out) const;
  // +AM2's colours of the tile's pixels.
  void recursive(Tracer<T>& tracer, int x0, int y0, int x1, int y1, std::vector<Color>& out) const;
  // The ray of +AM2's point (i, j) of pixel (x, y)'s grid of 2^(R−1) + 1 points a side, and its key.
  Ray<T> gridRay(int x, int y, int i, int j) const;
  uint64_t gridKey(int x, int y, int i, int j) const;

  const Camera<T>& camera_;
  AntialiasOptions aa_;
  uint64_t seed_;
  bool gi_;  // whether the rays' keys are read
  int x0_, y0_, stride_, rows_;      // +AM1: the traced pixels' area, with its border; +AM2: the corners'
  int cells_;                        // +AM2: 2^(R−1), the finest squares along a pixel's side
  std::vector<Color> raw_, compared_;  // the first rays' radiance and its compared colour
};

}  // namespace rt
