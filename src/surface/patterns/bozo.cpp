// bozo (and spotted, its other name): the noise itself, smooth blobs about a unit across (POV-Ray 3.7
// manual, "Bozo"; the noise: docs/povray-noise.md).
#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Bozo final : public Pattern {
 public:
  explicit Bozo(NoiseChoice n) : noise_(std::move(n)) {}
  double value(const glm::dvec3& p) const override { return noise(p, noise_.get()); }

 private:
  NoiseChoice noise_;
};

}  // namespace

std::unique_ptr<Pattern> makeBozo(const PatternArgs& a) { return std::make_unique<Bozo>(a.noise); }

}  // namespace rt
