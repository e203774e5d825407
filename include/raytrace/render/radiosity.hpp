// POV-Ray's radiosity drawn with -gi's gathering and irradiance cache (docs/gi.md, "POV-Ray's radiosity").
#pragma once

#include "raytrace/render/options.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

// With a radiosity block in the scene: gathering on, weighted as POV-Ray weighs it, with recursion_limit levels
// and the cache, unless the command line's -gi already chose the samples, levels and cache. Otherwise nothing.
void useRadiosity(RenderOptions& options, const SceneDesc& scene);

}  // namespace rt
