// agate: bands along z bent by the scalar turbulence sum (with the pigment's octaves, omega and lambda),
// scaled by agate_turb (POV-Ray 3.7 manual, "Agate"; measured: docs/povray-noise.md). A turbulence amount
// displaces the point first, as for other patterns.
#include <algorithm>
#include <cmath>
#include <iterator>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Agate final : public Pattern {
 public:
  explicit Agate(const PatternArgs& a) : turbulence_(a.turbulence), scale_(a.agateTurbulence), noise_(a.noise) {}
  double value(const glm::dvec3& p) const override {
    constexpr double kTwoPi = 6.28318530717958647692;
    const double t = scale_ * turbulenceSum(p, turbulence_, noise_.get());
    const double v = std::clamp(0.5 * (std::sin(kTwoPi * (1.3 * t + 1.1 * p.z)) + 1), 0.0, 1.0);
    return std::pow(v, 0.77);
  }

 private:
  Turbulence turbulence_;
  double scale_;
  NoiseChoice noise_;
};

}  // namespace

// Its own colour map: white to (0.95, 0.75, 0.5) at 0.5, (0.9, 0.7, 0.5) to (0.9, 0.7, 0.4) at 0.6, (1, 0.7, 0.4) to (0.6, 0.3, 0) at 1.
constexpr ColourStop kAgateStops[] = {
    {0, Color(1, 1, 1)}, {0.5, Color(0.95f, 0.75f, 0.5f)}, {0.5, Color(0.9f, 0.7f, 0.5f)}, {0.6, Color(0.9f, 0.7f, 0.4f)},
    {0.6, Color(1, 0.7f, 0.4f)}, {1, Color(0.6f, 0.3f, 0)}};
const DefaultMap kAgateMap{kAgateStops, std::size(kAgateStops)};

std::unique_ptr<Pattern> makeAgate(const PatternArgs& a) { return std::make_unique<Agate>(a); }

}  // namespace rt
