// The record of every ray the tracer follows for one pixel, and the course's two ways of printing it:
// `printrays` (docs/reference/csc473.md §a.3) and the decorated `pixeltrace` (§a.9). The tracer fills the records while
// it computes the colour (tracer.hpp), so what is printed is what was rendered.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raytrace/geometry/math.hpp"

namespace rt {

struct ShadowRecord {
  glm::dvec3 origin{0}, dir{0};
  bool occluded = false;
};

struct RayRecord {
  enum class Kind { Primary, Reflection, Refraction } kind = Kind::Primary;
  glm::dvec3 origin{0}, dir{0};
  bool hit = false;
  // The rest is set only on a hit.
  int objectId = 0;             // 1-based, file order
  std::string objectType;       // "Sphere", "Plane", …
  glm::dvec3 point{0}, normal{0};
  double t = 0;
  Color ambient{0}, diffuse{0}, specular{0}, reflection{0}, refraction{0};  // already weighted
  float local = 0, reflect = 0, transmit = 0;                                // the weights (§c.5)
  std::vector<ShadowRecord> shadows;
  std::vector<std::string> extraInfo;  // "into-object", "into-air", "total-internal-reflection"
  std::vector<RayRecord> children;     // the refraction ray before the reflection ray
  Color color{0};                      // what the ray returned: the sum above (clamped where the scene asks)
};

// With -gi, the gather rays of one pixel at one bounce in sum: recorded one by one, a 64,16 pixel would print a
// thousand trees. Bounce b's rays leave the hits of bounce b − 1 (the eye ray's hits for b = 1).
struct GatherSummary {
  uint64_t rays = 0;
  Color radiance{0};  // the sum of what they returned
};

// Prints the trees of one pixel (one per sample) after the line "Pixel: [x, y] Color: <color>", with the
// pixel's colour already formatted. `decorated` selects the pixeltrace layout with branches and shadow rays.
// `gathers`, one per bounce, follow the trees as "Gather bounce b: N rays, mean radiance {r g b}".
void printRayTrees(std::ostream& out, int x, int y, const std::string& color, const std::vector<RayRecord>& trees,
                   bool decorated, const std::vector<GatherSummary>& gathers = {});

}  // namespace rt
