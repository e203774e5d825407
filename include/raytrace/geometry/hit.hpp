// The record of a ray-object intersection, shared by eye, shadow, reflection and refraction rays.
#pragma once

#include "raytrace/geometry/math.hpp"

namespace rt {

template <class T> class Object;

template <class T> struct Hit {
  T t = T(0);                       // world-space ray parameter
  Vec3<T> point{0};                 // on the surface, re-projected by the shape (docs/reference/stability.md F4); the
                                    // course tier reports o + t·d instead (Scene::hitPoint)
  Vec3<T> normal{0};                // unit, geometric, pointing out of the object whatever side the ray is on
  const Object<T>* object = nullptr;

  // True when the ray arrives from outside, i.e. against the outward normal.
  template <class D> bool frontFace(const D& rayDir) const { return glm::dot(rayDir, normal) < T(0); }
};

}  // namespace rt
