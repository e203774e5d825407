// POV-Ray's fisheye (manual, "Fisheye projection"): a circle across the picture's height, its radius the
// angle from the view over half of `angle`; right and up's lengths widen it (x scaled by |right|/|up|).
// Outside the circle there is no ray. Measured from POV-Ray's rays (tests/render/test_camera.cpp).
#include <cmath>

#include "raytrace/scene/projection.hpp"

namespace rt {

std::optional<EyeRay> fisheyeRay(const ProjectionFrame& f, double us, double vs) {
  const double x = 2 * us * glm::length(f.right) / glm::length(f.up), y = 2 * vs;
  const double radius = std::hypot(x, y);
  if (radius > 1) return std::nullopt;
  if (radius == 0) return EyeRay{f.location, f.forward};
  const double phi = radius * f.angle / 2;
  const glm::dvec3 side = (x * glm::normalize(f.right) + y * glm::normalize(f.up)) / radius;
  return EyeRay{f.location, std::cos(phi) * f.forward + std::sin(phi) * side};
}

}  // namespace rt
