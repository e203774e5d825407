// How a POV-Ray light's strength varies over the scene: its emitter kind's shaping (scene/light_kind.hpp) and a
// light's fading with distance (POV-Ray 3.7 manual, "Light Fading").
#pragma once

#include "raytrace/geometry/math.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

struct LightShape {
  const LightKind* kind = nullptr;  // null: the same all around
  Emitter emitter;
  double fadeDistance = 0, fadePower = 0;

  explicit LightShape(const LightDesc& light);
  // Whether the light needs one: plain point lights do not.
  static bool needed(const LightDesc& light) { return light.spot || light.fadeDistance > 0; }

  // The factor on the light's colour at `point`, `distance` from the light along the unit `toPoint`.
  float at(const glm::dvec3& toPoint, double distance) const;
};

}  // namespace rt
