// POV-Ray's four cylinder projections: an angle across the picture turns the view about the cylinder's axis
// (up for types 1 and 3, right for 2 and 4); along the axis the ray climbs (1, 2) or its origin moves (3, 4).
// Fitted to POV-Ray's pictures (tests/render/test_camera.cpp).
#include <cmath>

#include "raytrace/scene/projection.hpp"

namespace rt {

template <int Type> std::optional<EyeRay> cylinderRay(const ProjectionFrame& f, double us, double vs) {
  constexpr bool vertical = Type == 1 || Type == 3, moving = Type == 3 || Type == 4;
  const glm::dvec3 across = glm::normalize(vertical ? f.right : f.up), axis = vertical ? f.up : f.right;
  const double turn = (vertical ? us : vs) * f.angle, along = vertical ? vs : us;
  const glm::dvec3 turned = std::cos(turn) * f.forward + std::sin(turn) * across;
  if (moving) return EyeRay{f.location + along * axis, turned};
  return EyeRay{f.location, turned + along * axis};
}

template std::optional<EyeRay> cylinderRay<1>(const ProjectionFrame&, double, double);
template std::optional<EyeRay> cylinderRay<2>(const ProjectionFrame&, double, double);
template std::optional<EyeRay> cylinderRay<3>(const ProjectionFrame&, double, double);
template std::optional<EyeRay> cylinderRay<4>(const ProjectionFrame&, double, double);

}  // namespace rt
