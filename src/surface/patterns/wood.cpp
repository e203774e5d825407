// wood: cylinders about the z axis, drawn with a triangle wave; its turbulence bends x and y by a sine of the
// turbulent offset instead of displacing the point (POV-Ray 3.7 manual, "Wood" and "Turbulence versus
// Turbulence Warp"; measured: docs/povray-noise.md).
#include <cmath>
#include <iterator>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Wood final : public Pattern {
 public:
  explicit Wood(const Turbulence& t) : turbulence_(t) {}
  double value(const glm::dvec3& p) const override {
    if (!turbulence_.on()) return std::hypot(p.x, p.y);
    constexpr double kTwoPi = 6.28318530717958647692;
    const glm::dvec3 d = turbulentOffset(p, turbulence_);
    const double x = p.x + std::sin(kTwoPi * (p.x + d.x) * turbulence_.amount.x);
    const double y = p.y + std::sin(kTwoPi * (p.y + d.y) * turbulence_.amount.y);
    return std::hypot(x, y);
  }

 private:
  Turbulence turbulence_;
};

}  // namespace

// Its own colour map: light brown below 0.6, dark brown above.
constexpr ColourStop kWoodStops[] = {
    {0.6, Color(0.666f, 0.312f, 0.2f)}, {0.6, Color(0.4f, 0.1333f, 0.066f)}};
const DefaultMap kWoodMap{kWoodStops, std::size(kWoodStops)};

std::unique_ptr<Pattern> makeWood(const PatternArgs& a) { return std::make_unique<Wood>(a.turbulence); }

}  // namespace rt
