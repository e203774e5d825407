#include "raytrace/precision.hpp"

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

// The largest coordinate a shape reaches, in its own space.
double largestCoordinate(const ShapeDesc& shape) {
  return std::visit(
      [](const auto& s) -> double {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, SphereDesc>) {
          return maxAbs(s.center) + s.radius;
        } else if constexpr (std::is_same_v<S, PlaneDesc>) {
          return std::abs(s.distance);
        } else if constexpr (std::is_same_v<S, TriangleDesc>) {
          return std::max({maxAbs(s.a), maxAbs(s.b), maxAbs(s.c)});
        } else if constexpr (std::is_same_v<S, BoxDesc>) {
          return std::max(maxAbs(s.min), maxAbs(s.max));
        } else if constexpr (std::is_same_v<S, ConeDesc>) {
          return std::max(maxAbs(s.base) + s.baseRadius, maxAbs(s.cap) + s.capRadius);
        } else {
          return std::max(maxAbs(s.base), maxAbs(s.cap)) + s.radius;
        }
      },
      shape);
}

// How much a transform can stretch (largest column norm) and shrink (smallest column norm) lengths, and how
// far it moves the origin. Enough for a budget: it bounds the world-space extents by a small factor.
struct Stretch {
  double most, least, shift;
};
Stretch stretch(const glm::dmat4& m) {
  double most = 0, least = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double n = glm::length(glm::dvec3(m[i]));
    most = std::max(most, n);
    least = std::min(least, n);
  }
  return {most, least, maxAbs(glm::dvec3(m[3]))};
}

}  // namespace

double precisionBudget(const SceneDesc& scene) {
  // Rays start at the camera or on a surface; lights are only their targets, so they do not count.
  double largest = maxAbs(scene.camera.location);
  double smallest = std::numeric_limits<double>::infinity();
  for (const ObjectDesc& o : scene.objects) {
    const Stretch s = stretch(o.worldFromObject);
    largest = std::max(largest, s.shift + s.most * largestCoordinate(o.shape));
    smallest = std::min(smallest, s.least * smallestFeature(o.shape));
  }
  if (!(smallest > 0) || std::isinf(smallest)) return std::max(largest, 1.0);
  return std::max(largest, 1.0) / smallest;
}

Arithmetic chooseArithmetic(const SceneDesc& scene, Arithmetic requested) {
  const double r = precisionBudget(scene);
  Arithmetic a = requested;
  if (a.precision == Precision::Auto) a.precision = r <= 1e3 ? Precision::Float : Precision::Double;
  if (a.sphere == SphereMethod::Auto) {
    a.sphere = (a.precision == Precision::Float && r <= 50) ? SphereMethod::Textbook : SphereMethod::Robust;
  }
  return a;
}

}  // namespace rt
