// Whole-image rendering: what `render` (and a .cli `write`) produces.
#pragma once

#include "raytrace/image.hpp"
#include "raytrace/precision.hpp"
#include "raytrace/scene_desc.hpp"
#include "raytrace/spawn.hpp"

namespace rt {

// Everything the command line can change about how a picture is made.
struct RenderOptions {
  Arithmetic arithmetic;                        // --precision, --sphere
  OffsetPolicy offset = OffsetPolicy::Relative;  // spawned-ray origins
};

// Renders the scene at width × height. Implemented by the shading module (issue 3).
Image render(const SceneDesc& scene, int width, int height, const RenderOptions& options);

}  // namespace rt
