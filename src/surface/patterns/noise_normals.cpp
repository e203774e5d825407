// bumps and dents as normals: POV-Ray bends the normal by its vector noise v(p) rather than by the slope of the
// pigments' values (POV-Ray 3.7 manual, "Bumps", "Dents": "a specialized normal perturbation function"). Fitted
// to POV-Ray's renders: bumps bends n to n + amount·v(p), dents to n + amount·noise(p)³·v(p); turbulence moves p
// first (makePattern).
#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class NoiseNormal final : public Pattern {
 public:
  NoiseNormal(NoiseChoice n, bool dents) : noise_(std::move(n)), dents_(dents) {}
  double value(const glm::dvec3& p) const override { return noise(p, noise_.get()); }
  bool hasBump() const override { return true; }
  glm::dvec3 bump(const glm::dvec3& p) const override {
    const double weight = dents_ ? value(p) * value(p) * value(p) : 1;
    return -weight * vectorNoise(p);
  }

 private:
  NoiseChoice noise_;
  bool dents_;
};

}  // namespace

std::unique_ptr<Pattern> makeBumpsNormal(const PatternArgs& a) { return std::make_unique<NoiseNormal>(a.noise, false); }
std::unique_ptr<Pattern> makeDentsNormal(const PatternArgs& a) { return std::make_unique<NoiseNormal>(a.noise, true); }

}  // namespace rt
