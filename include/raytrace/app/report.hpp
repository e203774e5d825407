// `sceneinfo`'s text (docs/reference/csc473.md §a.1).
#pragma once

#include <ostream>

#include "raytrace/scene/description.hpp"

namespace rt {

// `sceneinfo`: camera, lights and objects as the course lists them (§a.1).
void printSceneInfo(std::ostream& out, const SceneDesc& scene);

}  // namespace rt
