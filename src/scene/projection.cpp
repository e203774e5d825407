#include "raytrace/scene/projection.hpp"

#include <algorithm>

namespace rt {

// POV-Ray's default angles (the manual's camera section): 90° for every kind that takes one, 360° for
// spherical.
const std::vector<ProjectionKind>& projectionKinds() {
  static const std::vector<ProjectionKind> kinds = {
      {"perspective", 0, 90, true, false, perspectiveRay},
      {"orthographic", 0, 90, true, false, orthographicRay},
      {"cylinder", 1, 90, false, false, cylinderRay<1>},
      {"cylinder", 2, 90, false, false, cylinderRay<2>},
      {"cylinder", 3, 90, false, false, cylinderRay<3>},
      {"cylinder", 4, 90, false, false, cylinderRay<4>},
      {"ultra_wide_angle", 0, 90, false, false, ultraWideAngleRay},
      {"spherical", 0, 360, false, false, sphericalRay},
      {"fisheye", 0, 90, false, true, fisheyeRay},
      {"omnimax", 0, 90, false, true, omnimaxRay},
      {"panoramic", 0, 90, false, false, panoramicRay},
      {"mesh_camera", 0, 90, false, true, meshCameraRay},
  };
  return kinds;
}

const ProjectionKind* projectionNamed(std::string_view keyword, int type) {
  const auto& kinds = projectionKinds();
  const auto found = std::find_if(kinds.begin(), kinds.end(),
                                  [&](const ProjectionKind& k) { return k.keyword == keyword && k.type == type; });
  return found == kinds.end() ? nullptr : &*found;
}

const ProjectionKind& perspectiveProjection() { return projectionKinds().front(); }

}  // namespace rt
