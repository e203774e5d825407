#include "raytrace/scene/light_shape.hpp"

#include <cmath>

namespace rt {

LightShape::LightShape(const LightDesc& light) : fadeDistance(light.fadeDistance), fadePower(light.fadePower) {
  if (!light.spot) return;
  kind = light.spot->kind;
  const glm::dvec3 d = light.spot->pointAt - light.position;
  if (glm::length(d) > 0) emitter.axis = glm::normalize(d);
  emitter.radius = light.spot->radius;
  emitter.falloff = light.spot->falloff;
  emitter.tightness = light.spot->tightness;
  kind->prepare(emitter);
}

float LightShape::at(const glm::dvec3& toPoint, double distance) const {
  double f = kind ? kind->factor(emitter, toPoint, distance) : 1;
  if (fadeDistance > 0) f *= 2 / (1 + std::pow(distance / fadeDistance, fadePower));
  return float(f);
}

}  // namespace rt
