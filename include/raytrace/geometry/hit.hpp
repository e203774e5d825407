// The record of a ray-object intersection, shared by eye, shadow, reflection and refraction rays.
#pragma once

#include <cmath>

#include "raytrace/geometry/math.hpp"

namespace rt {

template <class T> class Object;

template <class T> struct Hit {
  T t = T(0);                       // world-space ray parameter
  Vec3<T> point{0};                 // on the surface, re-projected by the shape (docs/reference/stability.md F4); the
                                    // course tier reports o + t·d instead (Scene::hitPoint)
  Vec3<T> normal{0};                // unit, geometric, pointing out of the object whatever side the ray is on
  const Object<T>* object = nullptr;
  glm::vec<2, T> uv{0};             // the surface's uv coordinates, where a uv_mapping texture reads (the shapes that
                                    // have them fill it in; docs/povray-language.md, "Textures")

  // False when the shape's size is below what the arithmetic resolves there (a sphere of radius 1e-320, whose
  // hit point cannot be told from its centre): the normal has no direction. Such a shape is missed.
  bool hasNormal() const { return std::isfinite(normal.x + normal.y + normal.z); }

  // True when the ray arrives from outside, i.e. against the outward normal.
  template <class D> bool frontFace(const D& rayDir) const { return glm::dot(rayDir, normal) < T(0); }
};

}  // namespace rt
