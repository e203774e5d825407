// POV-Ray's `media` in an object's interior: light absorbed, emitted and scattered along a ray's way inside.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/pigment.hpp"

namespace rt {

// `scattering { type, colour eccentricity e extinction x }`: light from the scene's lights turned toward the
// viewer, in the share phase() gives, while `extinction`·colour more is taken from the light crossing it.
struct Scattering {
  int type = 1;  // 1 isotropic, 2 Mie haze, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein
  Color color{0};
  double eccentricity = 0;  // type 5's g
  double extinction = 1;

  // The share of light arriving from the unit direction `toLight` that leaves along the ray's unit `dir`. The
  // shapes are the manual's ("Scattering": Mie of Nishita et al., Rayleigh's 1 + cos², Henyey-Greenstein's
  // ellipse); their scales are measured with POV-Ray 3.7 on a lit box (tests/surface/test_media.cpp).
  double phase(const glm::dvec3& dir, const glm::dvec3& toLight) const;
};

// What reaches a point of a medium from the scene's lights: each light's unit direction and colour there.
class MediaLights {
 public:
  struct Arrival {
    glm::dvec3 toLight;
    Color color;
  };
  virtual ~MediaLights() = default;
  virtual void at(const glm::dvec3& point, std::vector<Arrival>& out) = 0;
};

// A medium as POV-Ray 3.7's sampling method 3 draws it, its absorption, emission and scattering scaled at
// each point by the product of its densities' colours.
struct Media {
  Color absorption{0};
  Color emission{0};
  std::optional<Scattering> scattering;
  int samples = 10;   // the minimum of `samples MIN, MAX`; POV-Ray's default
  int intervals = 1;  // POV-Ray 3.7's default for method 3
  int aaLevel = 3;
  double aaThreshold = 0.1;
  std::vector<std::shared_ptr<const Pigment>> densities;  // `density { … }` blocks, read in the medium's space
  glm::dmat4 fromWorld{1};  // world space to the medium's (the object's transforms after the interior, undone)

  // What a ray brings back across `distance` of the medium from `behind`, the light from past it, the way in at
  // `start` along the unit `dir`; `lights` lights a scattering medium. Measured with POV-Ray 3.7
  // (docs/povray-language.md, "Media"): each of the `intervals` equal parts of length L is cut into n =
  // max(2, ⌊samples/2⌋ + 1) steps of length h = L/n, and step k is read between the points k·L/(n + 1) and
  // (k + 1)·L/(n + 1) from the part's start (as if there were n + 1 steps). A step reads its middle too and
  // takes the mean of the three, or, where the light given off at those points differs by more than
  // aa_threshold (summed over the channels, times L), the mean of its two halves, read the same way, down to
  // aa_level points deep. A step adds its light given off ·h seen through the steps before it and lets
  // through e^(−extinction·h).
  Color through(const Color& behind, const glm::dvec3& start, const glm::dvec3& dir, double distance,
                MediaLights* lights = nullptr) const;
  // through() across several media at once, as in one interior or where media overlap or one holds another: at
  // each point their absorptions, emissions and scatterings add (the manual, "Multiple Density vs. Multiple
  // Media"), read with the samples, intervals, aa_level and aa_threshold of the first with the most intervals
  // (measured with POV-Ray 3.7: tests/surface/test_media.cpp).
  static Color through(const Media* const* media, size_t count, const Color& behind, const glm::dvec3& start,
                       const glm::dvec3& dir, double distance, MediaLights* lights = nullptr);
  // What light crossing `distance` of `media` (adding up) from `start` along the unit `dir` keeps:
  // e^(−extinction) summed as above.
  static Color kept(const std::vector<Media>& media, const glm::dvec3& start, const glm::dvec3& dir, double distance);
};

}  // namespace rt
