// The black hole warp (POV-Ray 3.7 manual, "Black Hole Warp"). A point at distance r < R from the centre has
// closeness c = 1 − r/R and is moved along the line from the centre by min(1, strength·c^falloff) of r: away
// from the centre (the pattern seems drawn in), or toward it with `inverse`. With `repeat` the centre is an
// offset into each block of that size.
#include <cmath>

#include "raytrace/surface/warp.hpp"

namespace rt {

namespace {

class BlackHoleWarp final : public Warp {
 public:
  explicit BlackHoleWarp(const BlackHoleArgs& a) : a_(a) {}

  glm::dvec3 apply(const glm::dvec3& p) const override {
    glm::dvec3 local = p;
    for (int k = 0; k < 3; ++k) {
      if (a_.repeat[k] != 0) local[k] -= a_.repeat[k] * std::floor(p[k] / a_.repeat[k]);
    }
    const glm::dvec3 d = local - a_.centre;
    const double r = glm::length(d);
    if (!(r < a_.radius)) return p;
    const double force = std::min(1.0, a_.strength * std::pow(1 - r / a_.radius, a_.falloff));
    return a_.inverse ? p - d * force : p + d * force;
  }

 private:
  BlackHoleArgs a_;
};

}  // namespace

std::unique_ptr<Warp> makeBlackHoleWarp(const BlackHoleArgs& args) { return std::make_unique<BlackHoleWarp>(args); }

}  // namespace rt
