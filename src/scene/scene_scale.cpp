#include "raytrace/scene/scene_scale.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace rt {

namespace {

double maxAbs(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// The smallest length a shape's silhouette depends on; planes have none.
double smallestFeature(const ShapeDesc& shape) {
  return std::visit(
      [](const auto& s) -> double {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, SphereDesc>) {
          return s.radius;
        } else if constexpr (std::is_same_v<S, TriangleDesc>) {
          return std::min({glm::length(s.b - s.a), glm::length(s.c - s.b), glm::length(s.a - s.c)});
        } else if constexpr (std::is_same_v<S, BoxDesc>) {
          const glm::dvec3 e = glm::abs(s.max - s.min);
          return std::min({e.x, e.y, e.z});
        } else if constexpr (std::is_same_v<S, ConeDesc>) {
          return std::min(glm::length(s.cap - s.base), std::max(s.baseRadius, s.capRadius));
        } else if constexpr (std::is_same_v<S, CylinderDesc>) {
          return std::min(glm::length(s.cap - s.base), s.radius);
        } else {
          return std::numeric_limits<double>::infinity();
        }
      },
      shape);
}

// A ball around the shape, in its own space. A plane is unbounded; its point nearest the origin stands in.
struct Ball {
  glm::dvec3 center;
  double radius;
};
Ball boundingBall(const ShapeDesc& shape) {
  return std::visit(
      [](const auto& s) -> Ball {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, SphereDesc>) {
          return {s.center, s.radius};
        } else if constexpr (std::is_same_v<S, PlaneDesc>) {
          return {s.distance * glm::normalize(s.normal), 0};
        } else if constexpr (std::is_same_v<S, TriangleDesc>) {
          const glm::dvec3 m = (s.a + s.b + s.c) / 3.0;
          return {m, std::max({glm::length(s.a - m), glm::length(s.b - m), glm::length(s.c - m)})};
        } else if constexpr (std::is_same_v<S, BoxDesc>) {
          return {(s.min + s.max) / 2.0, glm::length(s.max - s.min) / 2};
        } else if constexpr (std::is_same_v<S, ConeDesc>) {
          return {(s.base + s.cap) / 2.0, glm::length(s.cap - s.base) / 2 + std::max(s.baseRadius, s.capRadius)};
        } else {
          return {(s.base + s.cap) / 2.0, glm::length(s.cap - s.base) / 2 + s.radius};
        }
      },
      shape);
}

}  // namespace

Stretch stretch(const glm::dmat4& m) {
  double most = 0, least = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double n = glm::length(glm::dvec3(m[i]));
    most = std::max(most, n);
    least = std::min(least, n);
  }
  return {most, least};
}

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
    const glm::dmat4 worldFromObject = composeTransforms<double>(o.transforms, &largestTransform);
    const Stretch s = stretch(worldFromObject);
    const Ball local = boundingBall(o.shape);
    smallest = std::min(smallest, s.least * smallestFeature(o.shape));
    const glm::dvec3 center(worldFromObject * glm::dvec4(local.center, 1));
    const double radius = s.most * local.radius;
    largest = std::max(largest, maxAbs(center) + radius);
    lo = glm::min(lo, center - radius);
    hi = glm::max(hi, center + radius);
  }
  return {std::max({largest, glm::length(hi - lo), 1.0}), smallest, lo, hi, largestTransform};
}

double precisionBudget(const SceneDesc& scene) { return precisionBudget(sceneScale(scene)); }

}  // namespace rt
