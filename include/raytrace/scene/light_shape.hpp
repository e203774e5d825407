// How a POV-Ray light's strength varies over the scene: a spotlight's cone, a cylinder light's cylinder and a
// light's fading with distance (POV-Ray 3.7 manual, "Spotlights", "Cylindrical Lights" and "Light Fading"; the
// edges fitted to POV-Ray's pictures).
#pragma once

#include "raytrace/geometry/math.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

struct LightShape {
  bool spot = false;
  bool cylinder = false;  // a cylinder light: radius and falloff are distances from the axis
  double radius = 0, falloff = 0;
  glm::dvec3 axis{0, -1, 0};          // unit, from the light toward its point_at
  double cosRadius = 1, cosFalloff = 1, tightness = 0;
  double fadeDistance = 0, fadePower = 0;

  explicit LightShape(const LightDesc& light);
  // Whether the light needs one: plain point lights do not.
  static bool needed(const LightDesc& light) { return light.spot || light.fadeDistance > 0; }

  // The factor on the light's colour at `point`, `distance` from the light along the unit `toPoint`.
  float at(const glm::dvec3& toPoint, double distance) const;
};

}  // namespace rt
