// Test support: scenes assembled in code, object by object.
#pragma once

#include "raytrace/scene/description.hpp"

namespace rt::test {

inline void add(SceneDesc& scene, const ShapeDesc& shape, const Material& m) {
  ObjectDesc o;
  o.shape = shape;
  o.material = m;
  scene.objects.push_back(o);
}

}  // namespace rt::test
