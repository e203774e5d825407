// Warps (POV-Ray 3.7 manual, "Warp"): maps of texture space standing among a pattern's transforms, applied in
// the order written. One kind a file in src/surface/warps/, read by one row of parse/povray/warp_reader.cpp.
#pragma once

#include <memory>

#include "raytrace/geometry/math.hpp"
#include "raytrace/surface/noise.hpp"

namespace rt {

class Warp {
 public:
  virtual ~Warp() = default;
  // The point the pattern reads in place of p.
  virtual glm::dvec3 apply(const glm::dvec3& p) const = 0;
};

// `warp { turbulence T [octaves omega lambda] }`: p displaced by the turbulence's random walk.
std::unique_ptr<Warp> makeTurbulenceWarp(const Turbulence& turbulence);

// `warp { repeat W [offset O] [flip F] }`: W lies along one axis.
struct RepeatWarpArgs {
  int axis = 0;
  double width = 1;  // W's component along the axis; negative repeats the slice (W, 0]
  glm::dvec3 offset{0};
  glm::bvec3 flip{false};
};
std::unique_ptr<Warp> makeRepeatWarp(const RepeatWarpArgs& args);

// `warp { black_hole C, R [falloff F] [strength S] [inverse] [repeat V] }`.
struct BlackHoleArgs {
  glm::dvec3 centre{0};
  double radius = 1;
  double falloff = 2, strength = 1;
  bool inverse = false;
  glm::dvec3 repeat{0};  // 0 along an axis: no repetition along it
};
std::unique_ptr<Warp> makeBlackHoleWarp(const BlackHoleArgs& args);

// `warp { planar [N, D] }`: the pattern of a plane extruded along z; N is normalised.
std::unique_ptr<Warp> makePlanarWarp(const glm::dvec3& normal, double distance);

}  // namespace rt
