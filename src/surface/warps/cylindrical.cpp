// The cylindrical warp (POV-Ray 3.7 manual, "Mapping using warps"): the point at turn t round the y axis and
// distance ρ from it reads (t·ρ^dist_exp, y, ρ), turned by the orientation; a point on the axis stays where it
// is (as POV-Ray's pattern values show: docs/povray-noise.md, "Warps").
#include <cmath>

#include "raytrace/surface/warp.hpp"

namespace rt {

namespace {

class CylindricalWarp final : public Warp {
 public:
  explicit CylindricalWarp(const MappingWarpArgs& a) : a_(a) {}

  glm::dvec3 apply(const glm::dvec3& p) const override {
    const double rho = std::hypot(p.x, p.z);
    if (rho == 0) return p;
    return warpOriented(a_.orientation, {warpTurn(p.x, p.z) * std::pow(rho, a_.distExp), p.y, rho});
  }

 private:
  MappingWarpArgs a_;
};

}  // namespace

std::unique_ptr<Warp> makeCylindricalWarp(const MappingWarpArgs& args) {
  return std::make_unique<CylindricalWarp>(args);
}

}  // namespace rt
