// granite: six octaves of |1 − 2·noise|, each twice as fine and half as strong, at four times the noise's
// scale (POV-Ray 3.7 manual, "Granite"; the sum as measured from POV-Ray: docs/povray-noise.md).
#include <algorithm>
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Granite final : public Pattern {
 public:
  explicit Granite(NoiseChoice n) : noise_(std::move(n)) {}
  double value(const glm::dvec3& p) const override {
    const NoiseGenerator g = noise_.get();
    double sum = 0, freq = 1;
    for (int i = 0; i < 6; ++i, freq *= 2) {
      const double n = noise(p * (4 * freq), g);
      // The original generator's noise is centred on 0.5; the others' range is wider, hence the cap.
      const double t = g == NoiseGenerator::Original ? std::abs(0.5 - n) : std::min(std::abs(1 - 2 * n), 0.5);
      sum += t / freq;
    }
    return sum;
  }

 private:
  NoiseChoice noise_;
};

}  // namespace

std::unique_ptr<Pattern> makeGranite(const PatternArgs& a) { return std::make_unique<Granite>(a.noise); }

}  // namespace rt
