// spherical: 1 at the centre falling to 0 at the distance from the origin 1, and 0 beyond (POV-Ray 3.7 manual, "Spherical").
#include <algorithm>
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Spherical final : public Pattern {
 public:
  double value(const glm::dvec3& p) const override { return std::max(0.0, 1 - glm::length(p)); }
};

}  // namespace

std::unique_ptr<Pattern> makeSpherical(const PatternArgs&) { return std::make_unique<Spherical>(); }

}  // namespace rt
