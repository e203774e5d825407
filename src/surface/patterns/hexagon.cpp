// hexagon: hexagonal rods along y, their sides 1 long, in three colours: the one about the origin, the one next
// to it in +z and the two beside those (POV-Ray 3.7 manual, "Hexagon Pattern"). The hexagons' corners point
// along ±x; measured on POV-Ray's values, docs/povray-noise.md.
#include <cmath>

#include "raytrace/surface/patterns.hpp"

namespace rt {

namespace {

class Hexagon final : public Pattern {
 public:
  // The nearest centre of the lattice (1.5 i, 0, √3/2 i + √3 j) is in the column on either side of the point;
  // the colour (j − i) mod 3 gives every centre's six neighbours colours other than its own.
  double value(const glm::dvec3& p) const override {
    constexpr double kHalfRoot3 = 0.86602540378443864676;
    const double left = std::floor(p.x / 1.5);
    double best = HUGE_VAL, colour = 0;
    for (double i : {left, left + 1}) {
      const double j = std::round((p.z - i * kHalfRoot3) / (2 * kHalfRoot3));
      const double dx = p.x - 1.5 * i, dz = p.z - kHalfRoot3 * (i + 2 * j);
      const double d = dx * dx + dz * dz;
      if (d < best) {
        best = d;
        colour = std::fmod(j - i, 3.0);
        if (colour < 0) colour += 3;
      }
    }
    return colour;
  }
  int blocks() const override { return 3; }
  Color defaultBlock(int i) const override { return i == 0 ? Color(0, 0, 1) : i == 1 ? Color(0, 1, 0) : Color(1, 0, 0); }
};

}  // namespace

std::unique_ptr<Pattern> makeHexagon(const PatternArgs&) { return std::make_unique<Hexagon>(); }

}  // namespace rt
