// Whole-image rendering: what `render` (and a .cli `write`) produces.
#pragma once

#include <optional>
#include <ostream>

#include "raytrace/bvh.hpp"
#include "raytrace/image.hpp"
#include "raytrace/parallel.hpp"
#include "raytrace/precision.hpp"
#include "raytrace/scene_desc.hpp"
#include "raytrace/shading.hpp"
#include "raytrace/spawn.hpp"

namespace rt {

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
};

// Renders the scene at width × height.
Image render(const SceneDesc& scene, int width, int height, const RenderOptions& options);
// The same straight to the 8 bits a PNG holds, each channel converted by toByte() with the scene's convention.
Rgb8Image renderRgb8(const SceneDesc& scene, int width, int height, const RenderOptions& options);

}  // namespace rt
