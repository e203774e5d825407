// marble: the distance along x, drawn with a triangle wave; its turbulence is added to that distance as the
// scalar turbulence sum instead of displacing the point (POV-Ray 3.7 manual, "Marble" and "Turbulence versus
// Turbulence Warp"; measured: docs/povray-noise.md).
#include <iterator>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Marble final : public Pattern {
 public:
  Marble(const Turbulence& t, NoiseChoice n) : turbulence_(t), noise_(std::move(n)) {}
  double value(const glm::dvec3& p) const override {
    if (!turbulence_.on()) return p.x;
    return p.x + turbulence_.amount.x * turbulenceSum(p, turbulence_, noise_.get());
  }

 private:
  Turbulence turbulence_;
  NoiseChoice noise_;
};

}  // namespace

// Its own colour map: (0.9, 0.8, 0.8) to (0.9, 0.08, 0.08) at 0.9, then black.
constexpr ColourStop kMarbleStops[] = {
    {0, Color(0.9f, 0.8f, 0.8f)}, {0.9, Color(0.9f, 0.08f, 0.08f)}, {0.9, Color(0)}, {1, Color(0)}};
const DefaultMap kMarbleMap{kMarbleStops, std::size(kMarbleStops)};

std::unique_ptr<Pattern> makeMarble(const PatternArgs& a) { return std::make_unique<Marble>(a.turbulence, a.noise); }

}  // namespace rt
