// wrinkles: ten octaves of noise, each twice as fine and half as strong (POV-Ray 3.7 manual, "Wrinkles";
// the sum as measured from POV-Ray: docs/povray-noise.md).
#include <algorithm>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Wrinkles final : public Pattern {
 public:
  explicit Wrinkles(NoiseChoice n) : noise_(std::move(n)) {}
  double value(const glm::dvec3& p) const override {
    const NoiseGenerator g = noise_.get();
    // The original generator adds plain noise; the others 2·noise − 0.5, clamped to [0, 1].
    const auto octave = [g](const glm::dvec3& q) {
      const double n = noise(q, g);
      return g == NoiseGenerator::Original ? n : std::clamp(2 * n - 0.5, 0.0, 1.0);
    };
    double sum = octave(p), lambda = 2, omega = 0.5;
    for (int i = 1; i < 10; ++i, lambda *= 2, omega *= 0.5) sum += omega * octave(p * lambda);
    return sum / 2;
  }

 private:
  NoiseChoice noise_;
};

}  // namespace

std::unique_ptr<Pattern> makeWrinkles(const PatternArgs& a) { return std::make_unique<Wrinkles>(a.noise); }

}  // namespace rt
