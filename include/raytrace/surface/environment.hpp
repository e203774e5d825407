// What a ray meets outside the objects: POV-Ray's sky_sphere, seen where a ray leaves the scene, and its fogs,
// which every ray crosses on its way (POV-Ray 3.7 manual, "Sky Sphere" and "Fog").
#pragma once

#include <memory>
#include <vector>

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/noise.hpp"
#include "raytrace/surface/pattern.hpp"
#include "raytrace/surface/pigment.hpp"

namespace rt {

struct SkySphere {
  std::vector<std::shared_ptr<const Pigment>> layers;  // the bottom one first
  glm::dmat4 fromWorld{1};                             // undoes the sky's rotations
  bool filterTints = true;  // false for scenes before POV-Ray 3.7, whose skies let filtered light through untinted

  // The sky in the unit direction `dir`, over `background` where every layer lets it through.
  Color at(const glm::dvec3& dir, const Color& background) const;
  Color bound() const;  // each channel's largest value anywhere
};

struct Fog {
  enum class Type { Constant = 1, Ground = 2 } type = Type::Constant;
  Rgbft colour;
  double distance = 0;           // the depth at which 1/e of the light is left
  double offset = 0, alt = 0;    // ground fog: full density up to `offset`, a quarter at offset + alt
  glm::dvec3 up{0, 1, 0};
  Turbulence turbulence;         // off unless the fog says `turbulence`
  double turbDepth = 0.5;        // POV-Ray's default turb_depth
  NoiseChoice noise;             // the scene's noise_generator

  // What the fog does over `depth` world units of the ray from `origin` along the unit `dir` (an infinite
  // depth for a ray that leaves the scene): it multiplies the colour behind it by `through` and adds `added`.
  struct Effect {
    Color through, added;
  };
  Effect effect(const glm::dvec3& origin, const glm::dvec3& dir, double depth) const;
  // The colour `c` seen through this fog alone.
  Color over(const Color& c, const glm::dvec3& origin, const glm::dvec3& dir, double depth) const;
  // The share of the fog's thickness left by its turbulence along a ray of finite depth.
  double turbulentShare(const glm::dvec3& origin, const glm::dvec3& dir, double depth) const;
};

// `c` seen through all the scene's fogs: POV-Ray multiplies what each lets through and adds what each adds,
// so the order of the fogs does not matter (measured: two fogs give c·k1·k2 + (1 − k1)·C1 + (1 − k2)·C2).
Color throughFogs(const std::vector<Fog>& fogs, Color c, const glm::dvec3& origin, const glm::dvec3& dir, double depth);

}  // namespace rt
