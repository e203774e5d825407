// A POV object's transforms as the file writes them, and the matrix they compose to (docs/reference/csc473.md §c.10).
// Kept as steps so the matrix can be composed in either precision: the course tier (scene/arithmetic.hpp) needs the
// very float matrix the course's reference renderer builds, rounding included.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace rt {

struct TransformStep {
  enum class Kind { Translate, Scale, Rotate, Matrix } kind;
  glm::dvec3 v;  // the offset, the scale factors, or the rotation angles about x, y and z in degrees
  // POV-Ray's `matrix <m00, m01, m02, …, m30, m31, m32>` (Matrix only): the point (x, y, z) goes to
  // (x·m00 + y·m10 + z·m20 + m30, x·m01 + …), the manual's §3.3.1.12.4. Shared, so other steps stay small.
  std::shared_ptr<const std::array<double, 12>> matrix = nullptr;
};

// M = step_n ⋯ step_1: each step multiplies on the left, in T arithmetic, the way the course's reference
// builds it. `rotate <x,y,z>` is R = Rx·Ry·Rz, itself built from the identity by left-multiplying Rz, Ry, Rx
// in turn, so it turns about z first (§c.10; the opposite of POV-Ray's order). With `largest`, the largest
// magnitude of any entry of M and of every partial product on the way is written there: what composing in T
// must be able to hold.
template <class T>
glm::mat<4, 4, T, glm::defaultp> composeTransforms(const std::vector<TransformStep>& steps, T* largest = nullptr) {
  using M4 = glm::mat<4, 4, T, glm::defaultp>;
  using V3 = glm::vec<3, T, glm::defaultp>;
  const M4 identity(T(1));
  M4 m = identity;
  for (const TransformStep& s : steps) {
    const V3 v(s.v);
    switch (s.kind) {
      case TransformStep::Kind::Translate:
        m = glm::translate(identity, v) * m;
        break;
      case TransformStep::Kind::Scale:
        m = glm::scale(identity, v) * m;
        break;
      case TransformStep::Kind::Rotate: {
        M4 r = identity;
        r = glm::rotate(identity, glm::radians(v.z), V3(0, 0, 1)) * r;
        r = glm::rotate(identity, glm::radians(v.y), V3(0, 1, 0)) * r;
        r = glm::rotate(identity, glm::radians(v.x), V3(1, 0, 0)) * r;
        m = r * m;
        break;
      }
      case TransformStep::Kind::Matrix: {
        // Column i of the 4×4 matrix holds the manual's row i: glm's [column][row].
        M4 g = identity;
        for (int i = 0; i < 4; ++i) {
          for (int j = 0; j < 3; ++j) g[i][j] = T((*s.matrix)[size_t(i * 3 + j)]);
        }
        m = g * m;
        break;
      }
    }
    for (int i = 0; largest && i < 4; ++i) {
      for (int j = 0; j < 4; ++j) *largest = std::max(*largest, std::abs(m[i][j]));
    }
  }
  return m;
}

}  // namespace rt
