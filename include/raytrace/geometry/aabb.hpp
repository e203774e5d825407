// Axis-aligned bounding box, the unit of every acceleration structure.
#pragma once

#include <limits>

#include "raytrace/geometry/math.hpp"

namespace rt {

template <class T> struct Aabb {
  Vec3<T> min{std::numeric_limits<T>::infinity()};
  Vec3<T> max{-std::numeric_limits<T>::infinity()};

  void expand(const Vec3<T>& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void expand(const Aabb& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
};

}  // namespace rt
