// bozo (and spotted, its other name): the noise itself, smooth blobs about a unit across (POV-Ray 3.7
// manual, "Bozo"; the noise: docs/povray-noise.md).
#include <iterator>

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

// Its own colour map: white below 0.4, green to 0.6, blue to 0.8, red above.
constexpr ColourStop kBozoStops[] = {
    {0.4, Color(1, 1, 1)}, {0.4, Color(0, 1, 0)}, {0.6, Color(0, 1, 0)}, {0.6, Color(0, 0, 1)}, {0.8, Color(0, 0, 1)},
    {0.8, Color(1, 0, 0)}};
const DefaultMap kBozoMap{kBozoStops, std::size(kBozoStops)};

std::unique_ptr<Pattern> makeBozo(const PatternArgs& a) { return std::make_unique<Bozo>(a.noise); }

}  // namespace rt
