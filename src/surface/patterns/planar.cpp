// planar: 1 at the centre falling to 0 at the distance from the x-z plane 1, and 0 beyond (POV-Ray 3.7 manual, "Planar").
#include <algorithm>
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Planar final : public Pattern {
 public:
  double value(const glm::dvec3& p) const override { return std::max(0.0, 1 - std::abs(p.y)); }
};

}  // namespace

std::unique_ptr<Pattern> makePlanar(const PatternArgs&) { return std::make_unique<Planar>(); }

}  // namespace rt
