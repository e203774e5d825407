// onion: spherical shells a unit apart about the origin (POV-Ray 3.7 manual, "Onion").
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Onion final : public Pattern {
 public:
  double value(const glm::dvec3& p) const override {
    const double r = glm::length(p);
    return r - std::floor(r);
  }
};

}  // namespace

std::unique_ptr<Pattern> makeOnion(const PatternArgs&) { return std::make_unique<Onion>(); }

}  // namespace rt
