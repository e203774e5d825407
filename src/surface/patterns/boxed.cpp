// boxed: 1 at the centre falling to 0 at the largest coordinate's size 1, and 0 beyond (POV-Ray 3.7 manual, "Boxed").
#include <algorithm>
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Boxed final : public Pattern {
 public:
  double value(const glm::dvec3& p) const override { return std::max(0.0, 1 - std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)})); }
};

}  // namespace

std::unique_ptr<Pattern> makeBoxed(const PatternArgs&) { return std::make_unique<Boxed>(); }

}  // namespace rt
