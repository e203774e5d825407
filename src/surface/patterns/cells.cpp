// cells: each unit cube one random value (POV-Ray 3.7 manual, "Cells Pattern"; the values measured from
// POV-Ray: docs/povray-noise.md).
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Cells final : public Pattern {
 public:
  double value(const glm::dvec3& p) const override {
    return cellValue(int(std::floor(p.x)), int(std::floor(p.y)), int(std::floor(p.z)));
  }
};

}  // namespace

std::unique_ptr<Pattern> makeCells(const PatternArgs&) { return std::make_unique<Cells>(); }

}  // namespace rt
