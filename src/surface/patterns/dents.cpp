// dents as a pigment: the cube of the noise, mostly dark with sparse bright spots (POV-Ray 3.7 manual,
// "Dents"; measured: docs/povray-noise.md).
#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Dents final : public Pattern {
 public:
  explicit Dents(NoiseChoice n) : noise_(std::move(n)) {}
  double value(const glm::dvec3& p) const override {
    const double n = noise(p, noise_.get());
    return n * n * n;
  }

 private:
  NoiseChoice noise_;
};

}  // namespace

std::unique_ptr<Pattern> makeDents(const PatternArgs& a) { return std::make_unique<Dents>(a.noise); }

}  // namespace rt
