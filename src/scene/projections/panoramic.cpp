// POV-Ray's panoramic (manual, "Panoramic projection"): the cylindrical equirectangular projection, 180°
// across and 180° up, on the ellipsoid whose axes are the direction, right and up as written.
#include <cmath>

#include <glm/gtc/constants.hpp>

#include "raytrace/scene/projection.hpp"

namespace rt {

std::optional<EyeRay> panoramicRay(const ProjectionFrame& f, double us, double vs) {
  const double theta = us * glm::pi<double>(), phi = vs * glm::pi<double>();
  return EyeRay{f.location, std::cos(phi) * (std::cos(theta) * f.directionLength * f.forward +
                                             std::sin(theta) * f.right) +
                                std::sin(phi) * f.up};
}

}  // namespace rt
