// POV-Ray's ultra wide angle and spherical projections: the picture's sides are angles across and up, the ray
// on a box-like or a spherical grid of directions. Fitted to POV-Ray's pictures (tests/render/test_camera.cpp).
#include <cmath>

#include "raytrace/scene/projection.hpp"

namespace rt {

namespace {

EyeRay angular(const ProjectionFrame& f, double us, double vs, bool spherical) {
  const double a = us * f.angle, b = vs * f.verticalAngle;
  const double across = spherical ? std::sin(a) * std::cos(b) : std::sin(a);
  return {f.location, across * glm::normalize(f.right) + std::sin(b) * glm::normalize(f.up) +
                          std::cos(a) * std::cos(b) * f.forward};
}

}  // namespace

std::optional<EyeRay> ultraWideAngleRay(const ProjectionFrame& f, double us, double vs) {
  return angular(f, us, vs, false);
}

std::optional<EyeRay> sphericalRay(const ProjectionFrame& f, double us, double vs) {
  return angular(f, us, vs, true);
}

}  // namespace rt
