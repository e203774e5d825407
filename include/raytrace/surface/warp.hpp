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
  glm::dvec3 turbulence{0};  // with a repeat: how far each block's centre may stray, along each axis
};
std::unique_ptr<Warp> makeBlackHoleWarp(const BlackHoleArgs& args);

// `warp { planar [N, D] }`: the pattern of a plane extruded along z; N is normalised.
std::unique_ptr<Warp> makePlanarWarp(const glm::dvec3& normal, double distance);

// What the planar, cylindrical, spherical and toroidal warps make of their point v = (a, b, c) for the
// normalised orientation n: ((n_y + n_z)·a + n_x·c, (n_x + n_z)·b − n_y·c, −n_x·a + n_y·b + n_z·c), v itself
// for the default n = z (docs/povray-noise.md, "Warps").
glm::dvec3 warpOriented(const glm::dvec3& n, const glm::dvec3& v);
// The turn from +x toward +z round the y axis of the point (x, z), in [0, 1): 0 on the axis itself.
double warpTurn(double x, double z);

// `warp { cylindrical | spherical | toroidal [orientation O] [dist_exp E] [major_radius R] }`: the point's
// angles round the y axis (and round the torus's tube) as x and y, its distance as z.
struct MappingWarpArgs {
  glm::dvec3 orientation{0, 0, 1};  // normalised
  double distExp = 0;
  double majorRadius = 1;  // toroidal only
};
std::unique_ptr<Warp> makeCylindricalWarp(const MappingWarpArgs& args);
std::unique_ptr<Warp> makeSphericalWarp(const MappingWarpArgs& args);
std::unique_ptr<Warp> makeToroidalWarp(const MappingWarpArgs& args);

// `warp { cubic }`: the six faces of the cube round the origin unfolded onto the unit square as a box's
// uv_mapping lays them; z is the distance max(|x|, |y|, |z|).
std::unique_ptr<Warp> makeCubicWarp();

}  // namespace rt
