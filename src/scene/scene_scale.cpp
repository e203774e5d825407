#include "raytrace/scene/scene_scale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

namespace {

double maxAbs(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

}  // namespace

double precisionBudget(const SceneScale& s) {
  if (!(s.smallestFeature > 0) || std::isinf(s.smallestFeature)) return s.extent;
  return s.extent / s.smallestFeature;
}


SceneScale sceneScale(const SceneDesc& scene) {
  // Two lengths set the error: coordinates, whose rounding is ε relative to their magnitude, and the distance
  // a ray travels from its origin (the camera or a surface) to what it hits, which the sphere's t error
  // scales with (docs/reference/stability.md F1). The box around the camera and every bounded object bounds the second by
  // its diagonal. Lights are only targets of rays, so they do not count.
  double largest = maxAbs(scene.camera.location);
  glm::dvec3 lo = scene.camera.location, hi = scene.camera.location;
  double smallest = std::numeric_limits<double>::infinity();
  double largestTransform = 1;
  for (const ObjectDesc& o : scene.objects) {
    const WorldExtent e = worldExtent(o, &largestTransform);
    smallest = std::min(smallest, e.feature);
    const auto [center, radius] = e.ball;
    largest = std::max(largest, maxAbs(center) + radius);
    lo = glm::min(lo, center - radius);
    hi = glm::max(hi, center + radius);
  }
  return {std::max({largest, glm::length(hi - lo), 1.0}), smallest, lo, hi, largestTransform};
}

double precisionBudget(const SceneDesc& scene) { return precisionBudget(sceneScale(scene)); }

}  // namespace rt
