// A ray o + t·d. Directions are unit length except for object-space rays of transformed objects, whose t must
// stay the world t (docs/reference/csc473.md §c.10).
#pragma once

#include "raytrace/geometry/math.hpp"

namespace rt {

template <class T> struct Ray {
  Vec3<T> origin;
  Vec3<T> dir;

  Vec3<T> at(T t) const { return origin + t * dir; }
};

}  // namespace rt
