#include "raytrace/shapes/bicubic_patch.hpp"

namespace rt {

namespace {

// The cubic Bernstein polynomials at s, and their derivatives.
std::array<double, 4> bernstein(double s) {
  const double r = 1 - s;
  return {r * r * r, 3 * s * r * r, 3 * s * s * r, s * s * s};
}
std::array<double, 4> bernsteinSlope(double s) {
  const double r = 1 - s;
  return {-3 * r * r, 3 * r * r - 6 * s * r, 6 * s * r - 3 * s * s, 3 * s * s};
}

}  // namespace

MeshData bicubicPatchMesh(const std::array<glm::dvec3, 16>& p, int uSteps, int vSteps,
                          const std::array<glm::dvec2, 4>& uvCorners) {
  MeshData m;
  const int nu = 1 << uSteps, nv = 1 << vSteps;
  // The point at (u, v) is Σ Bᵢ(u)·Bⱼ(v)·p[4i + j]: u runs across the rows of the control points, v along a row
  // (as POV-Ray's pictures divide a patch).
  for (int j = 0; j <= nv; ++j) {
    const double v = double(j) / nv;
    const auto bv = bernstein(v), dv = bernsteinSlope(v);
    for (int i = 0; i <= nu; ++i) {
      const double u = double(i) / nu;
      const auto bu = bernstein(u), du = bernsteinSlope(u);
      glm::dvec3 point(0), alongU(0), alongV(0);
      for (size_t b = 0; b < 4; ++b) {
        for (size_t a = 0; a < 4; ++a) {
          point += bu[a] * bv[b] * p[4 * a + b];
          alongU += du[a] * bv[b] * p[4 * a + b];
          alongV += bu[a] * dv[b] * p[4 * a + b];
        }
      }
      m.vertices.push_back(point);
      // uv_mapping's coordinates: the uv_vectors of the four corners blended bilinearly (the manual's §3.4.6.7.2),
      // its u along a row of the control points, as POV-Ray's pictures show.
      m.uvs.push_back((1 - v) * (1 - u) * uvCorners[0] + v * (1 - u) * uvCorners[1] + v * u * uvCorners[2] +
                      (1 - v) * u * uvCorners[3]);
      // At a corner where control points coincide the normal is undefined: that corner is left flat.
      const glm::dvec3 n = glm::cross(alongU, alongV);
      m.normals.push_back(glm::length(n) > 0 ? glm::normalize(n) : glm::dvec3(0));
    }
  }
  const auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
    MeshData::Face f;
    f.v = {a, b, c};
    f.uv = {int32_t(a), int32_t(b), int32_t(c)};
    const bool smooth = m.normals[a] != glm::dvec3(0) && m.normals[b] != glm::dvec3(0) && m.normals[c] != glm::dvec3(0);
    if (smooth) f.n = {int32_t(a), int32_t(b), int32_t(c)};
    m.faces.push_back(f);
  };
  const uint32_t row = uint32_t(nu + 1);
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const uint32_t q = uint32_t(j) * row + uint32_t(i);
      add(q, q + 1, q + row + 1);
      add(q, q + row + 1, q + row);
    }
  }
  return m;
}

}  // namespace rt
