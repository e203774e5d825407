// Where each float tier is sound: the worst errors its arithmetic can make in one scene, as lengths on the
// image (pixels) or against the course's fixed offset. The bounds are derived in docs/accuracy.md
// ("Choosing the arithmetic"); chooseArithmetic() compares them with kVisiblePixels.
#pragma once

#include "raytrace/scene/description.hpp"

namespace rt {

// The grid of eye rays: the image's size times the samples per side (-ss=N).
struct View {
  int width = 640;
  int height = 480;
};

// Float's unit roundoff 2⁻²⁴: every float operation is exact to within this relative error.
constexpr double kFloatRoundoff = 0x1p-24;
// An edge that moves by less than this fraction of a pixel changes only pixels its exact position already
// grazes; beyond it, whole runs of pixels along the edge flip.
constexpr double kVisiblePixels = 0.25;
// A light's contribution below this (on 0–1) cannot change an 8-bit pixel by more than 2 levels.
constexpr double kVisibleLight = 2.0 / 255;

// Worst-case distance, in the sphere's own units, between the float answer and the true surface along a ray
// whose origin is D from the centre of a sphere of radius r. The textbook quadratic subtracts two terms of
// size D² (its discriminant's rounding is at most 16uD²), which moves the silhouette and the hit point by
// 8uD²/r; the robust test loses only the rounding of its inputs, 9uD.
double textbookSphereError(double D, double r);
double robustSphereError(double D);

// The smallest angle, in radians, between two neighbouring eye rays (at the image's corners).
double pixelAngle(const CameraDesc& camera, View view);

struct TierDomain {
  // The largest silhouette or hit-point error of a sphere, in pixels of the image at the sphere's distance,
  // for ray origins anywhere in the scene (the camera and every bounded object).
  double textbookPixels = 0;
  double robustPixels = 0;
  // The largest hit-point error of the textbook quadratic, in world units: it must stay well inside the
  // course's 0.001 offset, or a spawned ray starts under the surface.
  double textbookHitError = 0;
  // The largest shift, in pixels, of a shadow edge on a flat surface (plane, box face, triangle) that the
  // course's fixed offset causes: a shadow ray leaving at incidence φ is moved sideways by 0.001·sin φ, so
  // the edge moves 0.001·tan φ along the surface; counted only where the light changes a pixel visibly.
  double offsetShadowPixels = 0;
  // The largest shift, in pixels, of what is seen through a glass sphere near its silhouette, where the
  // refracted ray's offset origin moves its exit by up to 2·0.001/r radians.
  double offsetRefractionPixels = 0;
};
TierDomain tierDomain(const SceneDesc& scene, View view);

// The smallest clearance between two spheres closer than twice the course's offset, or between a sphere and a
// plane (negative: they overlap; +∞: none). Below twice the offset, a spawned ray can start inside the
// neighbour. Apart from tierDomain(): the sweep over pairs is the one cost that grows faster than the scene.
double smallestGap(const SceneDesc& scene);

}  // namespace rt
