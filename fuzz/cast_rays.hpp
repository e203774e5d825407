// What every fuzz target does with a scene that parsed: build it at the precision it asks for and cast a few
// eye rays, so that the numbers a file can smuggle in (huge, tiny, degenerate) reach the geometry under the
// sanitizers too. Scene construction may still refuse the scene with a ParseError.
#pragma once

#include "raytrace/render/camera.hpp"
#include "raytrace/scene/arithmetic.hpp"
#include "raytrace/accel/scene.hpp"

namespace rt::fuzz {

inline void castRays(const SceneDesc& desc) {
  const Arithmetic arithmetic = chooseArithmetic(desc);
  withPrecision(arithmetic.tier, [&](auto tag) {
    using T = decltype(tag);
    const Scene<T> scene(desc, arithmetic);
    const Camera<T> camera(desc.camera, 3, 3);
    for (int y = 0; y < 3; ++y) {
      for (int x = 0; x < 3; ++x) scene.closestHit(camera.pixelRay(x, y), {});
    }
  });
}

}  // namespace rt::fuzz
