// Whole-image rendering: what `render` (and a .cli `write`) produces.
#pragma once

#include <optional>
#include <ostream>

#include "raytrace/accel/bvh.hpp"
#include "raytrace/image/image.hpp"
#include "raytrace/image/region.hpp"
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
  std::ostream* progress = nullptr;              // where render() shows its progress line, if anywhere
  RenderTimes* times = nullptr;                  // where render() adds how long it took, if anywhere
};

// Renders the scene at width × height.
Image render(const SceneDesc& scene, int width, int height, const RenderOptions& options);
// Renders only the region of that picture: the same colours as those pixels of the whole render, bit for bit.
Image render(const SceneDesc& scene, int width, int height, const Region& region, const RenderOptions& options);
// The same straight to the 8 bits a PNG holds, each channel converted by toByte() with the scene's convention.
Rgb8Image renderRgb8(const SceneDesc& scene, int width, int height, const RenderOptions& options);

}  // namespace rt
