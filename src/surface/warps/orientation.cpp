// What the mapping warps share (POV-Ray 3.7 manual, "Mapping using warps"): the turn of their point round the y
// axis, and the `orientation` applied to the point they make, as POV-Ray's pattern values show
// (docs/povray-noise.md, "Warps").
#include <cmath>

#include "raytrace/surface/warp.hpp"

namespace rt {

glm::dvec3 warpOriented(const glm::dvec3& n, const glm::dvec3& v) {
  return {(n.y + n.z) * v.x + n.x * v.z, (n.x + n.z) * v.y - n.y * v.z, -n.x * v.x + n.y * v.y + n.z * v.z};
}

double warpTurn(double x, double z) {
  if (x == 0 && z == 0) return 0;  // atan2 of (±0, −0) would give a half turn
  constexpr double kTwoPi = 6.28318530717958647692;
  const double t = std::atan2(z, x) / kTwoPi;
  return t < 0 ? t + 1 : t;
}

}  // namespace rt
