// spiral1 N: N arms winding about the z axis like a screw, drawn with a triangle wave; the value climbs by 1 per
// unit of z and of distance from the axis and by N per turn (POV-Ray 3.7 manual, "Spiral1 Pattern"; the
// formula, its angle counted from the −y axis, fitted to POV-Ray's values, docs/povray-noise.md).
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

double spiralTurn(const glm::dvec3& p) {
  constexpr double kTwoPi = 6.28318530717958647692;
  if (p.x == 0 && p.y == 0) return 0;
  const double turn = std::atan2(p.y, p.x) / kTwoPi + 0.25;
  return turn < 0 ? turn + 1 : turn;
}

namespace {

class Spiral1 final : public Pattern {
 public:
  explicit Spiral1(double arms) : arms_(arms) {}
  double value(const glm::dvec3& p) const override { return p.z + std::hypot(p.x, p.y) + arms_ * spiralTurn(p); }

 private:
  double arms_;
};

}  // namespace

std::unique_ptr<Pattern> makeSpiral1(const PatternArgs& a) { return std::make_unique<Spiral1>(a.vector.x); }

}  // namespace rt
