// POV-Ray 3.7's thin-film iridescence, a finish's `irid { amount thickness T turbulence U }` (POV-Ray 3.7
// manual, "Iridescence", with global_settings' "Irid_Wavelength").
#pragma once

#include <memory>

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/noise.hpp"

namespace rt {

struct Iridescence {
  double amount = 0, thickness = 0, turbulence = 0;
  // global_settings' irid_wavelength and noise_generator, shared with the scene's reader since global_settings
  // may come after the finish.
  std::shared_ptr<const glm::dvec3> wavelengths;
  std::shared_ptr<const NoiseGenerator> noise;

  // What a light's colour is multiplied by, for its diffuse term and its highlight alike, at world point p
  // with cosines cosLight = n·l toward the light and cosEye = n·v toward the viewer. Each channel of wavelength
  // λ gives 1 + amount·cos(2π·d·(cosLight + cosEye) / λ), the film d = thickness·(1 + turbulence·(2s − 1))
  // thick, s the sum of 5 octaves of turbulence (omega 0.5, lambda 2) at p; not clamped, so that it may be
  // negative. Measured on POV-Ray's renders to 2·10⁻⁵ (tests/surface/test_iridescence.cpp).
  Color factor(const glm::dvec3& p, double cosLight, double cosEye) const;
};

}  // namespace rt
