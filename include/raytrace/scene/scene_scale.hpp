// The lengths that set how much a scene's arithmetic can lose (docs/accuracy.md, "The precision budget").
#pragma once

#include "raytrace/scene/description.hpp"
#include "raytrace/shapes/scale.hpp"

namespace rt {

// The two lengths the precision budget compares (docs/reference/stability.md §1.1).
struct SceneScale {
  // The largest coordinate or ray length, at least 1; ray lengths are bounded by the diagonal of the box
  // around the camera and the objects.
  double extent;
  double smallestFeature;  // +∞ when no object has one (planes only, or nothing)
  glm::dvec3 lo, hi;       // the box around the camera and every bounded object: where rays start
  // The largest entry of any object's transform and of the partial products composing it: the course tier
  // composes them in float (geometry/transform.hpp), so they must be in its range too.
  double largestTransform = 1;
};
SceneScale sceneScale(const SceneDesc& scene);

// The scene's precision budget R = extent ÷ smallest feature (the extent alone when there is no feature).
double precisionBudget(const SceneDesc& scene);
double precisionBudget(const SceneScale& scale);

}  // namespace rt
