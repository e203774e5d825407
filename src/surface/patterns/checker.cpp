// checker: unit cubes of two colours alternating along each axis (POV-Ray 3.7 manual, "Checker").
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Checker final : public Pattern {
 public:
  // A point on a face between cubes (a plane through the origin) counts with the cube above it; the nudge
  // keeps the float error of the hit point from choosing at random.
  double value(const glm::dvec3& p) const override {
    constexpr double kNudge = 1e-6;
    const double sum = std::floor(p.x + kNudge) + std::floor(p.y + kNudge) + std::floor(p.z + kNudge);
    return std::fmod(std::abs(sum), 2.0);
  }
  int blocks() const override { return 2; }
  Color defaultBlock(int i) const override { return i == 0 ? Color(0, 0, 1) : Color(0, 1, 0); }  // blue, green
};

}  // namespace

std::unique_ptr<Pattern> makeChecker(const PatternArgs&) { return std::make_unique<Checker>(); }

}  // namespace rt
