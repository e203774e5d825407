// spiral1 N: N arms winding about the z axis like a screw, drawn with a triangle wave; the value climbs by 1 per
// unit of z and of distance from the axis and by N per turn (POV-Ray 3.7 manual, "Spiral1 Pattern"; the
// formula, its angle counted from the −y axis, fitted to POV-Ray's values, docs/povray-noise.md).
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Spiral1 final : public Pattern {
 public:
  explicit Spiral1(double arms) : arms_(arms) {}
  double value(const glm::dvec3& p) const override {
    constexpr double kTwoPi = 6.28318530717958647692;
    // The angle about z from the −y axis, as a share of a turn in [0, 1).
    double turn = std::atan2(p.y, p.x) / kTwoPi + 0.25;
    if (turn < 0) turn += 1;
    return p.z + std::hypot(p.x, p.y) + arms_ * turn;
  }

 private:
  double arms_;
};

}  // namespace

std::unique_ptr<Pattern> makeSpiral1(const PatternArgs& a) { return std::make_unique<Spiral1>(a.vector.x); }

}  // namespace rt
