// Whole-image rendering: what `render` (and a .cli `write`) produces.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <ostream>
#include <vector>

#include "raytrace/accel/bvh.hpp"
#include "raytrace/image/image.hpp"
#include "raytrace/util/parallel.hpp"
#include "raytrace/scene/arithmetic.hpp"
#include "raytrace/scene/description.hpp"
#include "raytrace/render/shading.hpp"
#include "raytrace/geometry/spawn.hpp"

namespace rt {

// How long a render's steps took, in seconds (--stats); a file that writes several images adds them up.
struct RenderTimes {
  double build = 0;  // the scene's objects and their hierarchy
  double trace = 0;  // the pixels
};

// How many rays of each kind a render traced (--stats).
struct RayCounts {
  uint64_t eye = 0, gather = 0, shadow = 0, secondary = 0;  // secondary: reflection and refraction
  uint64_t total() const { return eye + gather + shadow + secondary; }
  RayCounts& operator+=(const RayCounts& o) {
    eye += o.eye, gather += o.gather, shadow += o.shadow, secondary += o.secondary;
    return *this;
  }
};

// -gi: Monte Carlo global illumination, the course's Program 6 model (docs/gi.md).
struct GiOptions {
  bool enabled = false;
  std::vector<int> samples{64, 16};  // -gi_samples=N,N…: gather rays per hit at bounce 1, 2, …
  std::optional<int> bounces;        // -gi_bounces=B: levels that gather (default: one per sample count)
  uint64_t seed = 0;                 // --seed N: an independent render of the same scene

  int bounceCount() const { return bounces ? *bounces : int(samples.size()); }
  // Gather rays per hit at `bounce` (0 = the eye ray's hit); past the list, its last count.
  int samplesAt(int bounce) const { return samples[std::min(size_t(bounce), samples.size() - 1)]; }
};

// Everything the command line can change about how a picture is made.
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
  std::ostream* progress = nullptr;              // where render() shows its progress line, if anywhere
  RenderTimes* times = nullptr;                  // where render() adds how long it took, if anywhere
  RayCounts* rays = nullptr;                     // where render() adds the rays it traced, if anywhere
};

// Renders the scene at width × height.
Image render(const SceneDesc& scene, int width, int height, const RenderOptions& options);
// The same straight to the 8 bits a PNG holds, each channel converted by toByte() with the scene's convention.
Rgb8Image renderRgb8(const SceneDesc& scene, int width, int height, const RenderOptions& options);

}  // namespace rt
