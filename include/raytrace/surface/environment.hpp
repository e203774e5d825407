// What a ray meets outside the objects: POV-Ray's sky_sphere, seen where a ray leaves the scene, and its fogs,
// which every ray crosses on its way (POV-Ray 3.7 manual, "Sky Sphere" and "Fog").
#pragma once

#include <memory>
#include <vector>

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/pigment.hpp"

namespace rt {

struct SkySphere {
  std::vector<std::shared_ptr<const Pigment>> layers;  // the bottom one first
  glm::dmat4 fromWorld{1};                             // undoes the sky's rotations
  bool filterTints = true;  // false for scenes before POV-Ray 3.7, whose skies let filtered light through untinted

  // The sky in the unit direction `dir`, over `background` where every layer lets it through.
  Color at(const glm::dvec3& dir, const Color& background) const;
  Color bound() const;  // each channel's largest value anywhere
};

struct Fog {
  enum class Type { Constant = 1, Ground = 2 } type = Type::Constant;
  Rgbft colour;
  double distance = 0;           // the depth at which 1/e of the light is left
  double offset = 0, alt = 0;    // ground fog: full density up to `offset`, a quarter at offset + alt
  glm::dvec3 up{0, 1, 0};

  // The colour `c` seen through the fog over `depth` world units of the ray from `origin` along the unit
  // `dir`; an infinite depth for a ray that leaves the scene.
  Color over(const Color& c, const glm::dvec3& origin, const glm::dvec3& dir, double depth) const;
};

}  // namespace rt
