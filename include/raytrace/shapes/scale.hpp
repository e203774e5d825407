// An object's lengths in the world, for the precision budget (scene/scene_scale): its kind's, under its
// transforms.
#pragma once

#include "raytrace/shapes/shape_desc.hpp"

namespace rt {

// How much a transform can stretch (largest column norm) and shrink (smallest column norm) lengths. Enough
// for a budget: it bounds the world-space extents by a small factor.
struct Stretch {
  double most, least;
};
Stretch stretch(const glm::dmat4& m);

// An object's lengths in the world, from its transforms composed once.
struct WorldExtent {
  double feature;  // the smallest length its silhouette depends on; +∞ for none (a plane)
  Ball ball;       // a ball around it; an unbounded object gives a point of it, with radius 0
};
// With `largestEntry`, the largest magnitude of the transform's entries and partial products is kept there
// (composeTransforms).
WorldExtent worldExtent(const ObjectDesc& o, double* largestEntry = nullptr);

}  // namespace rt
