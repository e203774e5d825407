// POV-Ray's mesh_camera (manual, "Mesh projection"): a pixel's rays start on faces of the camera's meshes, at
// the face's centroid (distributions 0 to 2) or at the point whose uv coordinates are the pixel's (3), and go
// against the face's normal N = (B − A) × (C − A), normalized: along it when the direction's z is negative. The
// location's z moves the origin by −z·N. The rows the faces are counted by, and where a pixel falls in uv, were
// measured on POV-Ray's pictures of small meshes (tests/render/test_mesh_camera.cpp).
#include <algorithm>
#include <cmath>

#include "raytrace/scene/projection.hpp"

namespace rt {

namespace {

glm::dvec3 faceNormal(const MeshCamera::Face& f) {
  return glm::normalize(glm::cross(f.corners[1] - f.corners[0], f.corners[2] - f.corners[0]));
}

// The barycentric weights of `p` in the face's uv triangle, when it lies inside (edges included).
std::optional<glm::dvec3> uvWeights(const MeshCamera::Face& f, glm::dvec2 p) {
  const glm::dvec2 e1 = f.uv[1] - f.uv[0], e2 = f.uv[2] - f.uv[0], d = p - f.uv[0];
  const double det = e1.x * e2.y - e1.y * e2.x;
  if (det == 0) return std::nullopt;
  const double b1 = (d.x * e2.y - d.y * e2.x) / det, b2 = (e1.x * d.y - e1.y * d.x) / det;
  const double tolerance = 1e-9;
  if (b1 < -tolerance || b2 < -tolerance || b1 + b2 > 1 + tolerance) return std::nullopt;
  return glm::dvec3(1 - b1 - b2, b1, b2);
}

}  // namespace

std::optional<EyeRay> MeshCamera::ray(double x, double y, int k, int width, int height) const {
  const Face* face = nullptr;
  glm::dvec3 weights(1.0 / 3);
  if (distribution == 3) {
    // u = x / width, v = 1 − y / height, as measured; POV-Ray's last column and first row stop half a pixel
    // short of the edge.
    const glm::dvec2 uv(std::min(x, width - 1.5) / width, 1 - std::max(y, 0.5) / height);
    for (const std::vector<Face>& mesh : meshes) {
      for (const Face& f : mesh) {
        if (const auto w = uvWeights(f, uv)) {
          face = &f;
          weights = *w;
          break;
        }
      }
      if (face) break;
    }
  } else {
    // Faces are counted across the rows from the top: the first two rows both take row 0's faces.
    const int column = int(std::floor(x + 0.5)), row = std::max(int(std::floor(y + 0.5)) - 1, 0);
    const auto pick = [&](const std::vector<Face>& mesh, size_t index) {
      if (index < mesh.size()) face = &mesh[index];
    };
    if (distribution == 0) {
      if (size_t(k) < meshes.size()) pick(meshes[size_t(k)], size_t(row) * size_t(width) + size_t(column));
    } else if (distribution == 1) {
      size_t index = size_t(k) * size_t(width) * size_t(height) + size_t(row) * size_t(width) + size_t(column);
      for (const std::vector<Face>& mesh : meshes) {
        if (index < mesh.size()) {
          face = &mesh[index];
          break;
        }
        index -= mesh.size();
      }
    } else {
      // Side by side, one block of width / meshes columns per mesh, the first on the left. Within its block a
      // pixel takes face row·(width / meshes) + column, its column counted across the whole picture: so
      // POV-Ray's pictures show it.
      const int block = std::max(width / int(meshes.size()), 1), m = column / block;
      if (size_t(m) < meshes.size()) pick(meshes[size_t(m)], size_t(row) * size_t(block) + size_t(column));
    }
  }
  if (!face) return std::nullopt;
  const glm::dvec3 point = weights.x * face->corners[0] + weights.y * face->corners[1] + weights.z * face->corners[2];
  glm::dvec3 normal = faceNormal(*face);
  if (smooth && distribution == 3 && face->normals[0] != glm::dvec3(0)) {
    // The corner normals blended as a smooth triangle's, turned to the face normal's side.
    const glm::dvec3 blended =
        glm::normalize(weights.x * face->normals[0] + weights.y * face->normals[1] + weights.z * face->normals[2]);
    normal = glm::dot(blended, normal) < 0 ? -blended : blended;
  }
  return EyeRay{point - offset * normal, reversed ? normal : -normal};
}

// The single ray of a picture's point: (us, vs) back to pixels from the top-left pixel's centre.
std::optional<EyeRay> meshCameraRay(const ProjectionFrame& f, double us, double vs) {
  return f.mesh->ray((us + 0.5) * f.width - 0.5, (0.5 - vs) * f.height - 0.5, 0, f.width, f.height);
}

}  // namespace rt
