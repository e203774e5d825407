// spiral2 N: spiral1's screw of N arms, as a triangle wave, added to rings about the z axis, as a triangle wave
// of the distance from the axis; the value climbs by 2 per unit of z and per unit of distance, by 2N per turn
// (POV-Ray 3.7 manual, "Spiral2 Pattern"; the sum fitted to POV-Ray's values, docs/povray-noise.md).
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

double triangle(double v) {
  v -= std::floor(v);
  return v < 0.5 ? 2 * v : 2 - 2 * v;
}

class Spiral2 final : public Pattern {
 public:
  explicit Spiral2(double arms) : arms_(arms) {}
  double value(const glm::dvec3& p) const override {
    const double radius = std::hypot(p.x, p.y);
    return triangle(p.z + radius + arms_ * spiralTurn(p)) + triangle(radius);
  }

 private:
  double arms_;
};

}  // namespace

std::unique_ptr<Pattern> makeSpiral2(const PatternArgs& a) { return std::make_unique<Spiral2>(a.vector.x); }

}  // namespace rt
