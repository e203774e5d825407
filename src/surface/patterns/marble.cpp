// marble: the distance along x, drawn with a triangle wave; its turbulence is added to that distance as the
// scalar turbulence sum instead of displacing the point (POV-Ray 3.7 manual, "Marble" and "Turbulence versus
// Turbulence Warp"; measured: docs/povray-noise.md).
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

std::unique_ptr<Pattern> makeMarble(const PatternArgs& a) { return std::make_unique<Marble>(a.turbulence, a.noise); }

}  // namespace rt
