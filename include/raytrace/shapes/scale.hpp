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

// The smallest length the object's silhouette depends on, in the world; +∞ for none (a plane).
double worldFeature(const ObjectDesc& o);
// A ball around the object in the world. An unbounded object gives a point of it, with radius 0.
Ball worldBall(const ObjectDesc& o);

}  // namespace rt
