#include "raytrace/surface/iridescence.hpp"

#include <cmath>

namespace rt {

Color Iridescence::factor(const glm::dvec3& p, double cosLight, double cosEye) const {
  double film = thickness;
  if (turbulence != 0) {
    Turbulence octaves;
    octaves.octaves = 5;
    octaves.omega = 0.5f;
    octaves.lambda = 2.0f;
    film *= 1 + turbulence * (2 * turbulenceSum(p, octaves, *noise) - 1);
  }
  // The phase a wave of wavelength λ takes over the film and back, in units of λ (the manual's "Iridescence").
  const double phase = 2 * M_PI * film * (cosLight + cosEye);
  const glm::dvec3& w = *wavelengths;
  return Color(float(1 + amount * std::cos(phase / w.x)), float(1 + amount * std::cos(phase / w.y)),
               float(1 + amount * std::cos(phase / w.z)));
}

}  // namespace rt
