#include "raytrace/scene/light_shape.hpp"

#include <algorithm>
#include <cmath>

namespace rt {

LightShape::LightShape(const LightDesc& light) : fadeDistance(light.fadeDistance), fadePower(light.fadePower) {
  if (!light.spot) return;
  spot = true;
  const glm::dvec3 d = light.spot->pointAt - light.position;
  if (glm::length(d) > 0) axis = glm::normalize(d);
  if (light.spot->cylinder) {
    cylinder = true;
    radius = light.spot->radius;
    falloff = light.spot->falloff;
    return;
  }
  cosRadius = std::cos(glm::radians(light.spot->radius));
  cosFalloff = std::cos(glm::radians(light.spot->falloff));
  tightness = light.spot->tightness;
}

float LightShape::at(const glm::dvec3& toPoint, double distance) const {
  double f = 1;
  if (cylinder) {
    // Lit ahead of the light only; full within the radius of the axis, none past the falloff, and between
    // them the same smoothstep, in the distance (fitted to POV-Ray's pictures).
    const double along = glm::dot(toPoint, axis);
    if (along <= 0) return 0;
    const double across = distance * std::sqrt(std::max(0.0, 1 - along * along));
    if (across >= falloff) return 0;
    if (across > radius) {
      const double t = (falloff - across) / (falloff - radius);
      f = t * t * (3 - 2 * t);
    }
  } else if (spot) {
    // Full inside the radius cone, none outside the falloff cone, and between them a smoothstep in the
    // cosine; all of it times cos^tightness.
    const double c = glm::dot(toPoint, axis);
    if (c <= cosFalloff) return 0;
    if (c < cosRadius) {
      const double t = (c - cosFalloff) / (cosRadius - cosFalloff);
      f = t * t * (3 - 2 * t);
    }
    if (tightness != 0) f *= std::pow(c, tightness);
  }
  if (fadeDistance > 0) f *= 2 / (1 + std::pow(distance / fadeDistance, fadePower));
  return float(f);
}

}  // namespace rt
