// The picture-plane projections: perspective (the course's camera, docs/reference/csc473.md §d) and POV-Ray's
// orthographic.
#include "raytrace/scene/projection.hpp"

namespace rt {

// Through the picture plane's point one unit ahead: d = Us·right + Vs·up + forward.
std::optional<EyeRay> perspectiveRay(const ProjectionFrame& f, double us, double vs) {
  return EyeRay{f.location, us * f.right + vs * f.up + f.forward};
}

// Parallel rays along the view, from the picture's point on the plane through the location.
std::optional<EyeRay> orthographicRay(const ProjectionFrame& f, double us, double vs) {
  return EyeRay{f.location + us * f.right + vs * f.up, f.forward};
}

}  // namespace rt
