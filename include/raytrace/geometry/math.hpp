// Vector aliases shared by every module. All vector math is GLM; these names only say what a vector means.
#pragma once

#include <glm/glm.hpp>

namespace rt {

// Geometry is templated on the scalar T (float or double), chosen per scene by the precision budget
// (see scene/arithmetic.hpp). Colours are always float: 24 mantissa bits are far more than an 8-bit pixel needs.
template <class T> using Vec3 = glm::vec<3, T, glm::defaultp>;
template <class T> using Mat4 = glm::mat<4, 4, T, glm::defaultp>;
using Color = glm::vec3;

// Largest absolute component, the magnitude that floating-point error scales with.
template <class T> T maxAbs(const Vec3<T>& v) {
  return glm::max(glm::abs(v.x), glm::max(glm::abs(v.y), glm::abs(v.z)));
}

}  // namespace rt
