// POV-Ray's `media` in an object's interior: light absorbed and emitted along a ray's way inside.
#pragma once

#include <memory>
#include <vector>

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/pigment.hpp"

namespace rt {

// A medium without scattering as POV-Ray 3.7's sampling method 3 draws it, its absorption and emission scaled
// at each point by the product of its densities' colours.
struct Media {
  Color absorption{0};
  Color emission{0};
  int samples = 10;   // the minimum of `samples MIN, MAX`; POV-Ray's default
  int intervals = 1;  // POV-Ray 3.7's default for method 3
  std::vector<std::shared_ptr<const Pigment>> densities;  // `density { … }` blocks, read in the medium's space
  glm::dmat4 fromWorld{1};  // world space to the medium's (the object's transforms after the interior, undone)

  // What a ray brings back across `distance` of the medium from `behind`, the light from past it, the way in at
  // `start` along the unit `dir`. Each of the `intervals` equal parts of the way is cut into n = max(2,
  // ⌊samples/2⌋ + 1) steps of length h; step k of a part of length L reads the density at L·(k + ½)/(n + 1)
  // from the part's start, adds emission·h seen through the steps before it, and lets through e^(−absorption·h).
  // This rule (steps placed as if there were n + 1) is measured with POV-Ray 3.7 (docs/povray-language.md, "Media").
  Color through(const Color& behind, const glm::dvec3& start, const glm::dvec3& dir, double distance) const;
};

}  // namespace rt
