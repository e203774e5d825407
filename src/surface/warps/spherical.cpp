// The spherical warp (POV-Ray 3.7 manual, "Mapping using warps"): the point at turn t round the y axis,
// latitude φ and distance r from the origin reads (t·r^dist_exp, (1/2 + φ/π)·r^dist_exp, r), turned by the
// orientation; the origin stays where it is (as POV-Ray's pattern values show: docs/povray-noise.md, "Warps").
#include <algorithm>
#include <cmath>

#include "raytrace/surface/warp.hpp"

namespace rt {

namespace {

class SphericalWarp final : public Warp {
 public:
  explicit SphericalWarp(const MappingWarpArgs& a) : a_(a) {}

  glm::dvec3 apply(const glm::dvec3& p) const override {
    constexpr double kPi = 3.14159265358979323846;
    const double r = glm::length(p);
    if (r == 0) return p;
    const double scale = std::pow(r, a_.distExp);
    const double latitude = std::asin(std::clamp(p.y / r, -1.0, 1.0));
    return warpOriented(a_.orientation, {warpTurn(p.x, p.z) * scale, (0.5 + latitude / kPi) * scale, r});
  }

 private:
  MappingWarpArgs a_;
};

}  // namespace

std::unique_ptr<Warp> makeSphericalWarp(const MappingWarpArgs& args) { return std::make_unique<SphericalWarp>(args); }

}  // namespace rt
