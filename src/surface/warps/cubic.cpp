// The cubic warp (POV-Ray 3.7 manual, "Mapping using warps", and "Box UV mapping"): the point's face of the
// cube round the origin (its largest coordinate, ties going to +x, +y, −x, −y, +z, −z in that order) and its
// place q = p / max(|x|, |y|, |z|) on it read the box's uv layout: a row of −x, +z, +x, −z faces each a quarter
// wide across the middle third, +y above +z and −y below it; z is the distance. The origin stays where it is
// (as POV-Ray's pattern values show: docs/povray-noise.md, "Warps").
#include <algorithm>
#include <cmath>

#include "raytrace/surface/warp.hpp"

namespace rt {

namespace {

class CubicWarp final : public Warp {
 public:
  glm::dvec3 apply(const glm::dvec3& p) const override {
    const double w = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    if (w == 0) return p;
    const glm::dvec3 q = p / w;
    if (p.x == w) return {0.625 - q.z / 8, 0.5 + q.y / 6, w};
    if (p.y == w) return {0.375 + q.x / 8, 5.0 / 6 - q.z / 6, w};
    if (-p.x == w) return {0.125 + q.z / 8, 0.5 + q.y / 6, w};
    if (-p.y == w) return {0.375 + q.x / 8, 1.0 / 6 + q.z / 6, w};
    if (p.z == w) return {0.375 + q.x / 8, 0.5 + q.y / 6, w};
    return {0.875 - q.x / 8, 0.5 + q.y / 6, w};
  }
};

}  // namespace

std::unique_ptr<Warp> makeCubicWarp() { return std::make_unique<CubicWarp>(); }

}  // namespace rt
