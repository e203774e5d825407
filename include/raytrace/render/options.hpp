// What the command line can change about the pixels of a picture, and the threads that compute them.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "raytrace/accel/bvh.hpp"
#include "raytrace/render/shading.hpp"
#include "raytrace/scene/arithmetic.hpp"
#include "raytrace/util/parallel.hpp"

namespace rt {

// -gi: Monte Carlo global illumination, the course's Program 6 model (docs/gi.md).
struct GiOptions {
  bool enabled = false;
  std::vector<int> samples{64, 16};  // -gi_samples=N,N…: gather rays per hit at bounce 1, 2, …
  std::optional<int> bounces;        // -gi_bounces=B: levels that gather (default: one per sample count)
  uint64_t seed = 0;                 // --seed N: an independent render of the same scene
  // --gi-cache=A: the first bounce's gathering comes from an irradiance cache of accuracy A (docs/gi.md).
  std::optional<float> cache;
  // POV-Ray's radiosity (render/radiosity.hpp): the gathered light lights a surface as its diffuse colour takes
  // light, times `brightness`, grayed by `grayThreshold`, beside the material's own ambient (its emission).
  bool radiosity = false;
  float brightness = 1, grayThreshold = 0;

  int bounceCount() const { return bounces ? *bounces : int(samples.size()); }
  // Gather rays per hit at `bounce` (0 = the eye ray's hit); past the list, its last count.
  int samplesAt(int bounce) const { return samples[std::min(size_t(bounce), samples.size() - 1)]; }
};

// --aa, --aa-threshold, --aa-depth, --jitter: POV-Ray's adaptive anti-aliasing (+A, +AM, +R, +J;
// docs/povray-command-line.md), render/antialias.
struct AntialiasOptions {
  int method = 0;           // 0 off; 1 POV-Ray's non-recursive +AM1; 2 its recursive +AM2
  float threshold = 0.3f;   // the colour difference above which a pixel (or a square of +AM2) is refined
  int depth = 3;            // +R: R x R more rays (+AM1), or R − 1 levels of subdivision (+AM2)
  float jitter = 0;         // +J: how far samples move at random within their cell, 0 to 1
};

struct RenderOptions {
  Arithmetic arithmetic;                         // --precision, --sphere, --offset
  Brdf brdf = Brdf::BlinnPhong;                  // -altbrdf: Cook-Torrance (§c.2)
  bool fresnel = false;                          // -fresnel: Schlick-weighted reflection and refraction (§c.5)
  bool beers = false;                            // -beers: Beer's-law absorption instead of the ×C tint (§c.6)
  bool normals = false;                          // -normals: colour = n/2 + 0.5, a debug view
  int samples = 1;                               // -ss=N: N×N stratified eye rays per pixel (§c.12)
  std::optional<int> depth;                      // --depth=N: deepest secondary ray, instead of the scene's
  Hierarchy hierarchy = Hierarchy::Auto;         // --hierarchy: force the BVH on or off, for comparisons
  int threads = defaultThreads();                // --threads N
  GiOptions gi;                                  // -gi, -gi_samples, -gi_bounces, --seed
  AntialiasOptions aa;                           // --aa, --aa-threshold, --aa-depth, --jitter
};

}  // namespace rt
