// POV-Ray's bicubic_patch (the manual's §3.4.5.2.1): the Bézier surface of 16 control points, drawn as POV-Ray
// draws it, as smooth triangles over a grid of 2^u_steps by 2^v_steps pieces.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "raytrace/shapes/triangle_mesh.hpp"
#include "raytrace/util/format.hpp"

namespace rt {

// The triangles of the patch whose control points are `p` (four rows of four), 2^uSteps pieces across the rows
// and 2^vSteps along them, with the surface's normals at their corners.
MeshData bicubicPatchMesh(const std::array<glm::dvec3, 16>& p, int uSteps, int vSteps,
                          const std::array<glm::dvec2, 4>& uvCorners = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});

// The most steps either way: 2^10 × 2^10 pieces are two million triangles.
constexpr int kMaxPatchSteps = 10;

// The number after u_steps or v_steps.
template <class Reader> int patchSteps(Reader& r) {
  const SourceLoc at = r.here();
  const double n = r.number("the patch steps");
  if (!(n >= 0 && n <= kMaxPatchSteps && n == double(int(n)))) {
    throw ParseError(at, "the patch steps must be a whole number from 0 to " + std::to_string(kMaxPatchSteps) +
                             ", found " + shortest(n));
  }
  return int(n);
}

// `bicubic_patch { type t [flatness f] [u_steps n] [v_steps m] <16 points> }`, its items in any order. flatness
// only lets POV-Ray stop dividing where the patch is flat enough already: the full grid is the same surface
// to within it, so it changes nothing here.
template <class Reader> MeshData readBicubicPatch(Reader& r) {
  const SourceLoc at = r.here();
  bool typed = false;
  int steps[2] = {0, 0};
  for (;;) {
    const SourceLoc itemAt = r.here();
    if (r.keyword("type")) {
      const double type = r.number("the patch type");
      if (type != 0 && type != 1) throw ParseError(itemAt, "the patch type must be 0 or 1, found " + shortest(type));
      typed = true;
    } else if (r.keyword("flatness")) {
      r.nonNegative("the patch flatness");
    } else if (r.keyword("u_steps")) {
      steps[0] = patchSteps(r);
    } else if (r.keyword("v_steps")) {
      steps[1] = patchSteps(r);
    } else {
      break;
    }
  }
  if (!typed) throw ParseError(at, "'bicubic_patch' needs its type");
  std::array<glm::dvec2, 4> uv{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  if (r.keyword("uv_vectors")) {
    for (glm::dvec2& corner : uv) corner = glm::dvec2(r.vec3("a corner's uv vector"));
  }
  std::array<glm::dvec3, 16> p;
  for (glm::dvec3& point : p) point = r.vec3("a control point of the patch");
  return bicubicPatchMesh(p, steps[0], steps[1], uv);
}

}  // namespace rt
