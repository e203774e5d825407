// POV-Ray 3.7's solid noise and turbulence, reproduced to the last bit of a double so that patterns built on
// them (bozo, granite, wood, marble, agate, wrinkles, turbulence) give POV-Ray's pictures. How each function
// was measured from POV-Ray's own output: docs/povray-noise.md.
#pragma once

#include "raytrace/geometry/math.hpp"

namespace rt {

// global_settings' noise_generator, or a pattern's own: 1 the original noise, 2 the same with its range
// stretched toward [0, 1] (POV-Ray 3.7's default), 3 a gradient noise of its own (called Perlin's by the manual).
enum class NoiseGenerator : unsigned char { Original = 1, RangeCorrected = 2, Perlin = 3 };
// The generator a noise_generator number names, its fraction dropped as POV-Ray does (3.5 is 3).
inline NoiseGenerator noiseGeneratorOf(double n) {
  if (n >= 3 && n < 4) return NoiseGenerator::Perlin;
  return n < 2 ? NoiseGenerator::Original : NoiseGenerator::RangeCorrected;
}

// Smooth noise in [0, 1], varying over unit distances.
double noise(const glm::dvec3& p, NoiseGenerator g);
// Three independent noises, each about [-0.5, 0.5]: POV-Ray's vector noise, which turbulence displaces by.
glm::dvec3 vectorNoise(const glm::dvec3& p);

// The cells of crackle and cells: each unit cube [x, x+1) × [y, y+1) × [z, z+1) holds one random point, and
// cells gives the cube a random value; both from a table POV-Ray fills with the Mersenne Twister's default
// sequence, found by the same lattice hash as the noise's without its shift (docs/povray-noise.md).
glm::dvec3 cellPoint(int x, int y, int z);
double cellValue(int x, int y, int z);

// turbulence's modifiers. POV-Ray keeps omega and lambda in single precision, which shows in its pictures.
struct Turbulence {
  glm::dvec3 amount{0};
  int octaves = 6;
  float omega = 0.5f, lambda = 2.0f;
  bool on() const { return amount != glm::dvec3(0); }
};

// The displacement of turbulence: octaves of vector noise, each lambda times finer and omega times weaker.
glm::dvec3 turbulentOffset(const glm::dvec3& p, const Turbulence& t);
// The scalar sum of the same octaves that agate and marble read.
double turbulenceSum(const glm::dvec3& p, const Turbulence& t, NoiseGenerator g);

}  // namespace rt
