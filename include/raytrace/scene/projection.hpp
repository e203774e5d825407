// Camera projections (docs/povray-language.md, "Cameras"): how a point of the picture becomes an eye ray. A
// kind is one file in src/scene/projections/ (its ray, declared below) and one row of projectionKinds()
// (src/scene/projection.cpp); the POV-Ray camera reader and Camera<T> reach it through that row.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "raytrace/geometry/math.hpp"

namespace rt {

// What a projection reads of the camera: its place, the picture's right and up (not normalized), the unit
// view direction and the direction's length as written, and the angles (radians) POV-Ray's kinds take.
struct ProjectionFrame {
  glm::dvec3 location, right, up, forward;
  double directionLength = 1, angle = 0, verticalAngle = 0;
};

struct EyeRay {
  glm::dvec3 origin, dir;  // dir need not be unit
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

}  // namespace rt
