// What the command line can change about the pixels of a picture, and the threads that compute them.
#pragma once

#include <optional>

#include "raytrace/accel/bvh.hpp"
#include "raytrace/render/shading.hpp"
#include "raytrace/scene/arithmetic.hpp"
#include "raytrace/util/parallel.hpp"

namespace rt {

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
};

}  // namespace rt
