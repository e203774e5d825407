// POV-Ray's `normal { … }`: a pattern whose slope bends the shading normal at a hit, leaving the surface where
// it is (docs/povray-language.md, "Normals").
#pragma once

#include <memory>
#include <vector>

#include "raytrace/surface/pigment.hpp"

namespace rt {

// `[value, <height, slope>]` of a slope_map, in increasing values.
struct SlopeEntry {
  double value, height, slope;
};

struct Normal;

// A normal_map's entry (its value), a block pattern's normal (in order), or an average's (its weight).
struct NormalEntry {
  double value;
  std::shared_ptr<const Normal> normal;
};

struct Normal {
  std::shared_ptr<const Pattern> pattern;  // none for an average
  std::vector<NormalEntry> map;            // when set, the entries bend the normal instead of the pattern's slope
  bool average = false;                    // the map's normals weighted by their values
  double amount = 0.5;      // the number after the pattern, or bump_size
  double accuracy = 0.02;   // the distance of the sampled points from the hit
  bool bumpScale = true;    // no_bump_scale clears it
  std::vector<SlopeEntry> slopes;  // none: the height is the pattern's value
  glm::dmat4 fromTexture{1};       // texture space to the pattern's own
  // Warps as a pigment's (Pigment::warps); with any, the bumps are sampled round the warped point, and bend the
  // normal as the transforms alone would.
  std::vector<WarpStage> warps;
  glm::dmat4 afterWarps{1};
  double frequency = 1, phase = 0, exponent = 1;
  Wave wave = Wave::Ramp;

  // The unit normal n bent at p, a point of texture space; toTexture is the linear part of the map from world
  // space to texture space.
  glm::dvec3 bent(const glm::dvec3& n, const glm::dvec3& p, const glm::dmat3& toTexture) const;
  // The bump's height at q, a point of the pattern's space.
  double height(const glm::dvec3& q) const;

 private:
  // The normal bent by the map's entries at q, a point of the pattern's space; m maps world space to it.
  glm::dvec3 mapped(const glm::dvec3& n, const glm::dvec3& q, const glm::dmat3& m) const;
};

}  // namespace rt
