// POV-Ray's `media` in an object's interior: light absorbed and emitted along a ray's way inside.
#pragma once

#include "raytrace/geometry/math.hpp"

namespace rt {

// A homogeneous medium (no density pattern, no scattering) as POV-Ray 3.7's sampling method 3 draws it.
struct Media {
  Color absorption{0};
  Color emission{0};
  int samples = 10;  // the minimum of `samples MIN, MAX`; POV-Ray's default

  // What a ray brings back across `distance` of the medium from `behind`, the light from past it: behind·e^(−a·d)
  // plus the emission of n equal steps of length h = d/n, each seen through the medium before its near end,
  // e·h·Σ_{k<n} e^(−a·k·h), with n = max(2, ⌊samples/2⌋ + 1). The steps and the exact transmittance are
  // measured with POV-Ray 3.7 (docs/povray-language.md, "Media"); they hold for any `intervals`.
  Color through(const Color& behind, float distance) const;
};

}  // namespace rt
