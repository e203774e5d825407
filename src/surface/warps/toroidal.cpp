// The toroidal warp (POV-Ray 3.7 manual, "Mapping using warps"): for the point at turn t round the y axis, at
// offset (Δ, y) from the torus's core circle of radius major_radius (Δ its distance from the axis less the
// radius) and distance d from it, the turn s of (−Δ, −y) round the tube (0 on its inner equator, 1/2 on the
// outer) reads (t·d^dist_exp, s·d^dist_exp, d), turned by the orientation. A point on the y axis stays where it
// is, and one on the core circle reads the origin (as POV-Ray's pattern values show: docs/povray-noise.md).
#include <cmath>

#include "raytrace/surface/warp.hpp"

namespace rt {

namespace {

class ToroidalWarp final : public Warp {
 public:
  explicit ToroidalWarp(const MappingWarpArgs& a) : a_(a) {}

  glm::dvec3 apply(const glm::dvec3& p) const override {
    const double rho = std::hypot(p.x, p.z);
    if (rho == 0) return p;
    const double delta = rho - a_.majorRadius;
    const double d = std::hypot(delta, p.y);
    if (d == 0) return glm::dvec3(0);
    const double scale = std::pow(d, a_.distExp);
    return warpOriented(a_.orientation, {warpTurn(p.x, p.z) * scale, warpTurn(-delta, -p.y) * scale, d});
  }

 private:
  MappingWarpArgs a_;
};

}  // namespace

std::unique_ptr<Warp> makeToroidalWarp(const MappingWarpArgs& args) { return std::make_unique<ToroidalWarp>(args); }

}  // namespace rt
