// global_settings' `radiosity { … }` block (POV-Ray 3.7 manual, "Adjusting Radiosity"). Part of the scene
// builder (scene_builder.cpp).
#pragma once

#include "raytrace/parse/povray/surface_reader.hpp"
#include "raytrace/scene/radiosity.hpp"

namespace rt::povray {

// The block's settings over the manual's defaults. A setting that needs a number and has none, or a count out of
// 1 to 10^7, stops with a located error; anything else in the block is refused as not supported yet.
RadiosityDesc readRadiosity(const Node& n, ReadingContext& context);

}  // namespace rt::povray
