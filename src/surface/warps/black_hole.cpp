// The black hole warp (POV-Ray 3.7 manual, "Black Hole Warp"). A point at distance r < R from the centre has
// closeness c = 1 − r/R and is moved along the line from the centre by min(1, strength·c^falloff) of r: away
// from the centre (the pattern seems drawn in), or toward it with `inverse`. With `repeat` the centre is an
// offset into each block of that size; along a repeated axis a centre nearer the block's side than the radius is
// moved to the radius, and a block too small for the hole and its turbulence is enlarged to fit them, as the
// manual says and POV-Ray's values show. With a repeat, `turbulence T` moves each block's centre by T times
// that block's random point of crackle (cellPoint) less its corner, on every axis; without, it does nothing
// (measured on POV-Ray: docs/povray-noise.md, "Warps").
#include <cmath>

#include "raytrace/surface/noise.hpp"
#include "raytrace/surface/warp.hpp"

namespace rt {

namespace {

class BlackHoleWarp final : public Warp {
 public:
  explicit BlackHoleWarp(const BlackHoleArgs& a) : a_(a) {
    for (int k = 0; k < 3; ++k) {
      if (a_.repeat[k] == 0) continue;
      a_.centre[k] = std::max(a_.centre[k], a_.radius);
      a_.repeat[k] = std::max(a_.repeat[k], a_.centre[k] + a_.radius + a_.turbulence[k]);
      strays_ = a_.turbulence != glm::dvec3(0);
    }
  }

  glm::dvec3 apply(const glm::dvec3& p) const override {
    glm::dvec3 local = p, centre = a_.centre;
    glm::ivec3 block(0);
    for (int k = 0; k < 3; ++k) {
      if (a_.repeat[k] == 0) continue;
      block[k] = int(std::floor(p[k] / a_.repeat[k]));
      local[k] -= a_.repeat[k] * block[k];
    }
    if (strays_) centre += a_.turbulence * (cellPoint(block.x, block.y, block.z) - glm::dvec3(block));
    const glm::dvec3 d = local - centre;
    const double r = glm::length(d);
    if (!(r < a_.radius)) return p;
    const double force = std::min(1.0, a_.strength * std::pow(1 - r / a_.radius, a_.falloff));
    return a_.inverse ? p - d * force : p + d * force;
  }

 private:
  BlackHoleArgs a_;
  bool strays_ = false;  // a repeat and a turbulence
};

}  // namespace

std::unique_ptr<Warp> makeBlackHoleWarp(const BlackHoleArgs& args) { return std::make_unique<BlackHoleWarp>(args); }

}  // namespace rt
