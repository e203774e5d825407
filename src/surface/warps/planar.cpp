// The planar warp (POV-Ray 3.7 manual, "Mapping using warps"): the pattern in the plane across N at distance D,
// extruded along z. As POV-Ray's pattern values show (docs/povray-noise.md, "Warps"), the point (x, y, z)
// reads (n_y + n_z)·x + D·n_x, (n_x + n_z)·y − D·n_y, −n_x·x + n_y·y + D·n_z: the plane's pattern turned onto
// the x-y plane for a normal along an axis, and stretched as POV-Ray stretches it for any other.
#include "raytrace/surface/warp.hpp"

namespace rt {

namespace {

class PlanarWarp final : public Warp {
 public:
  PlanarWarp(const glm::dvec3& n, double d) : n_(n), d_(d) {}

  glm::dvec3 apply(const glm::dvec3& p) const override {
    return {(n_.y + n_.z) * p.x + d_ * n_.x, (n_.x + n_.z) * p.y - d_ * n_.y, -n_.x * p.x + n_.y * p.y + d_ * n_.z};
  }

 private:
  glm::dvec3 n_;
  double d_;
};

}  // namespace

std::unique_ptr<Warp> makePlanarWarp(const glm::dvec3& normal, double distance) {
  return std::make_unique<PlanarWarp>(normal, distance);
}

}  // namespace rt
