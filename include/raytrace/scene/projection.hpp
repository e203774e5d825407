// Camera projections (docs/povray-language.md, "Cameras"): how a point of the picture becomes an eye ray. A
// kind is one file in src/scene/projections/ (its ray, declared below) and one row of projectionKinds()
// (src/scene/projection.cpp); the POV-Ray camera reader and Camera<T> reach it through that row.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "raytrace/geometry/math.hpp"

namespace rt {

struct EyeRay {
  glm::dvec3 origin, dir;  // dir need not be unit
};

// POV-Ray's mesh_camera (manual, "Mesh projection"): each pixel's rays start on faces of meshes given in world
// space. Measured against POV-Ray's rays (tests/render/test_mesh_camera.cpp).
struct MeshCamera {
  struct Face {
    std::array<glm::dvec3, 3> corners;
    std::array<glm::dvec3, 3> normals;  // a smooth face's corner normals; zero for a flat face
    std::array<glm::dvec2, 3> uv;       // (0, 0) at corners without uv vectors
  };
  std::vector<std::vector<Face>> meshes;  // each mesh's faces, in file order
  int raysPerPixel = 1, distribution = 0;
  double offset = 0;      // the location's z: the origin moves −offset along the face's normal
  bool reversed = false;  // a direction whose z is negative: rays go along the normal, not against it
  bool smooth = false;    // distribution 3 interpolates the corner normals

  // Ray `k` of the pixel at column x, row y (row 0 the top) of a width × height picture, or nothing where no
  // face gives one. Distribution 3 takes the point within the picture, (x, y) in pixels from the top-left
  // pixel's centre; the others take the pixel holding it.
  std::optional<EyeRay> ray(double x, double y, int k, int width, int height) const;
};

// What a projection reads of the camera: its place, the picture's right and up (not normalized), the unit
// view direction and the direction's length as written, and the angles (radians) POV-Ray's kinds take.
struct ProjectionFrame {
  glm::dvec3 location, right, up, forward;
  double directionLength = 1, angle = 0, verticalAngle = 0;
  const MeshCamera* mesh = nullptr;  // the mesh camera's faces, and the picture's size they are indexed by
  int width = 1, height = 1;
};

// The eye ray through the picture's point (us, vs) ∈ [−½, ½]² (us across to the right, vs up), or nothing
// where the projection draws no picture (POV-Ray leaves those pixels black).
using ProjectionRay = std::optional<EyeRay> (*)(const ProjectionFrame&, double us, double vs);

struct ProjectionKind {
  std::string_view keyword;  // POV-Ray's word; the cylinders are "cylinder" with their type
  int type = 0;              // the cylinder's type, 1 to 4; 0 for the others
  double defaultAngle = 90;  // degrees, when the camera gives none
  // Whether `angle` sets the direction's length (a picture plane's field of view) rather than the
  // projection's own angle.
  bool planar = false;
  bool blanks = false;  // whether some of the picture's points have no ray
  ProjectionRay ray = nullptr;
};

const std::vector<ProjectionKind>& projectionKinds();
// The row of a keyword (and cylinder type), or null.
const ProjectionKind* projectionNamed(std::string_view keyword, int type = 0);
const ProjectionKind& perspectiveProjection();

// The kinds' rays, one file each in src/scene/projections/.
std::optional<EyeRay> perspectiveRay(const ProjectionFrame&, double us, double vs);
std::optional<EyeRay> orthographicRay(const ProjectionFrame&, double us, double vs);
template <int Type> std::optional<EyeRay> cylinderRay(const ProjectionFrame&, double us, double vs);
std::optional<EyeRay> ultraWideAngleRay(const ProjectionFrame&, double us, double vs);
std::optional<EyeRay> sphericalRay(const ProjectionFrame&, double us, double vs);
std::optional<EyeRay> fisheyeRay(const ProjectionFrame&, double us, double vs);
std::optional<EyeRay> omnimaxRay(const ProjectionFrame&, double us, double vs);
std::optional<EyeRay> panoramicRay(const ProjectionFrame&, double us, double vs);
std::optional<EyeRay> meshCameraRay(const ProjectionFrame&, double us, double vs);

}  // namespace rt
