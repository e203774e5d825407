#include "raytrace/shapes/scale.hpp"

#include <algorithm>
#include <limits>

namespace rt {

Stretch stretch(const glm::dmat4& m) {
  double most = 0, least = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double n = glm::length(glm::dvec3(m[i]));
    most = std::max(most, n);
    least = std::min(least, n);
  }
  return {most, least};
}

WorldExtent worldExtent(const ObjectDesc& o, double* largestEntry) {
  const glm::dmat4 worldFromObject = composeTransforms<double>(o.transforms, largestEntry);
  const Stretch s = stretch(worldFromObject);
  const double feature = std::visit([](const auto& k) { return k.smallestFeature(); }, o.shape);
  const Ball local = std::visit([](const auto& k) { return k.boundingBall(); }, o.shape);
  return {s.least * feature, {glm::dvec3(worldFromObject * glm::dvec4(local.center, 1)), s.most * local.radius}};
}

}  // namespace rt
