// POV-Ray's cylinder light (manual, "Cylindrical Lights"): lit ahead of the light only; full within the radius
// of the axis, none past the falloff, and between them the same smoothstep as a spotlight's, in the distance
// from the axis (fitted to POV-Ray's pictures).
#include <algorithm>
#include <cmath>

#include "raytrace/scene/light_kind.hpp"

namespace rt {

// Radius and falloff are lengths, read as written.
void prepareCylinderLight(Emitter&) {}

double cylinderLightFactor(const Emitter& e, const glm::dvec3& toPoint, double distance) {
  const double along = glm::dot(toPoint, e.axis);
  if (along <= 0) return 0;
  const double across = distance * std::sqrt(std::max(0.0, 1 - along * along));
  if (across >= e.falloff) return 0;
  if (across <= e.radius) return 1;
  const double t = (e.falloff - across) / (e.falloff - e.radius);
  return t * t * (3 - 2 * t);
}

}  // namespace rt
