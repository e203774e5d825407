// POV-Ray's omnimax (manual, "Omnimax projection"): a 180° fisheye whose circle the picture's top touches,
// with the dome's lens curve instead of the fisheye's straight one, and nothing more than 45° below the view.
// Every constant is measured from POV-Ray's rays over whole pictures at several |right|/|up| (the fit's
// error is under 3e-5 rad; tests/render/test_camera.cpp).
#include <algorithm>
#include <cmath>

#include "raytrace/scene/projection.hpp"

namespace rt {

std::optional<EyeRay> omnimaxRay(const ProjectionFrame& f, double us, double vs) {
  // Up to 1 the picture's width is the circle's and its height stretches by |up|/|right|; wider pictures are
  // lowered so that their top stays on the circle, and past 1.2834 their width grows instead.
  const double aspect = glm::length(f.right) / glm::length(f.up);
  double x = 2 * us, y = 2 * vs / aspect;
  if (aspect > 1) {
    const double s = std::max(1 / aspect, 0.77915);
    x = 2 * us * aspect * s;
    y = 2 * vs * s + 1 - s;
  }
  const double radius = std::hypot(x, y);
  if (radius > 1) return std::nullopt;
  // The angle from the view against the radius: an odd quintic (measured).
  const double r2 = radius * radius;
  const double theta = radius * (1.41126637 + r2 * (-0.09438341 + r2 * 0.25673606));
  const double across = radius > 0 ? x / radius : 0, up = radius > 0 ? y / radius : 0;
  const double sideways = std::sin(theta), ahead = std::cos(theta);
  if (sideways * up < -ahead) return std::nullopt;
  return EyeRay{f.location, ahead * f.forward + sideways * (across * glm::normalize(f.right) +
                                                            up * glm::normalize(f.up))};
}

}  // namespace rt
