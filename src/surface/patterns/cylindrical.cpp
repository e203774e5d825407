// cylindrical: 1 at the centre falling to 0 at the distance from the y axis 1, and 0 beyond (POV-Ray 3.7 manual, "Cylindrical").
#include <algorithm>
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Cylindrical final : public Pattern {
 public:
  double value(const glm::dvec3& p) const override { return std::max(0.0, 1 - std::hypot(p.x, p.z)); }
};

}  // namespace

std::unique_ptr<Pattern> makeCylindrical(const PatternArgs&) { return std::make_unique<Cylindrical>(); }

}  // namespace rt
