// The planar warp (POV-Ray 3.7 manual, "Mapping using warps"): the pattern in the plane across N at distance D,
// extruded along z. As POV-Ray's pattern values show (docs/povray-noise.md, "Warps"), the point (x, y, z)
// reads (x, y, D) turned by the orientation N as the other mapping warps turn theirs: the plane's pattern turned
// onto the x-y plane for a normal along an axis, and stretched as POV-Ray stretches it for any other.
#include "raytrace/surface/warp.hpp"

namespace rt {

namespace {

class PlanarWarp final : public Warp {
 public:
  PlanarWarp(const glm::dvec3& n, double d) : n_(n), d_(d) {}

  glm::dvec3 apply(const glm::dvec3& p) const override { return warpOriented(n_, {p.x, p.y, d_}); }

 private:
  glm::dvec3 n_;
  double d_;
};

}  // namespace

std::unique_ptr<Warp> makePlanarWarp(const glm::dvec3& normal, double distance) {
  return std::make_unique<PlanarWarp>(normal, distance);
}

}  // namespace rt
