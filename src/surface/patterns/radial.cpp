// radial: the angle about the y axis, 0 at +x, a quarter turn at −z (POV-Ray 3.7 manual, "Radial").
#include <cmath>
#include <iterator>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Radial final : public Pattern {
 public:
  double value(const glm::dvec3& p) const override {
    constexpr double kTurn = 2 * 3.14159265358979323846;
    const double a = std::atan2(-p.z, p.x) / kTurn;
    return a < 0 ? a + 1 : a;
  }
};

}  // namespace

// Its own colour map: cyan, yellow at 0.333, magenta at 0.666, cyan at 1.
constexpr ColourStop kRadialStops[] = {
    {0, Color(0, 1, 1)}, {0.333, Color(1, 1, 0)}, {0.666, Color(1, 0, 1)}, {1, Color(0, 1, 1)}};
const DefaultMap kRadialMap{kRadialStops, std::size(kRadialStops)};

std::unique_ptr<Pattern> makeRadial(const PatternArgs&) { return std::make_unique<Radial>(); }

}  // namespace rt
