// POV-Ray's spotlight (manual, "Spotlights"): full inside the radius cone, none outside the falloff cone, and
// between them a smoothstep in the cosine; all of it times cos^tightness (the edges fitted to POV-Ray's pictures).
#include <cmath>

#include "raytrace/scene/light_kind.hpp"

namespace rt {

// The cones' angles become their cosines.
void prepareSpotlight(Emitter& e) {
  e.radius = std::cos(glm::radians(e.radius));
  e.falloff = std::cos(glm::radians(e.falloff));
}

double spotlightFactor(const Emitter& e, const glm::dvec3& toPoint, double) {
  const double c = glm::dot(toPoint, e.axis);
  if (c <= e.falloff) return 0;
  double f = 1;
  if (c < e.radius) {
    const double t = (c - e.falloff) / (e.radius - e.falloff);
    f = t * t * (3 - 2 * t);
  }
  if (e.tightness != 0) f *= std::pow(c, e.tightness);
  return f;
}

}  // namespace rt
