// The one way every command turns a description into what it traces, so that render and the commands that
// inspect one pixel always trace the same scene.
#pragma once

#include <type_traits>

#include "raytrace/accel/scene.hpp"
#include "raytrace/render/camera.hpp"
#include "raytrace/render/options.hpp"
#include "raytrace/scene/arithmetic.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

// The eye rays' grid the arithmetic is chosen for: a supersampled pixel's rays are as close together as a
// grid `samples` times finer. A command without an image size gets the default view.
inline View eyeRayGrid(int width, int height, const RenderOptions& options) {
  if (width <= 0 || height <= 0) return View{};
  return View{width * options.samples, height * options.samples};
}

// Chooses the arithmetic for eye rays on `grid`, builds Scene<T> at that precision with `hierarchy`, and
// returns f(scene).
template <class F>
decltype(auto) withSceneAlone(const SceneDesc& desc, View grid, const RenderOptions& options, Hierarchy hierarchy,
                              F&& f) {
  const Arithmetic arithmetic = chooseArithmetic(desc, options.arithmetic, grid);
  return withPrecision(arithmetic.tier, [&](auto tag) {
    const Scene<decltype(tag)> scene(desc, arithmetic, hierarchy, options.threads);
    return f(scene);
  });
}

// The same with the scene's camera for a width × height picture: f(scene, camera).
template <class F>
decltype(auto) withScene(const SceneDesc& desc, int width, int height, const RenderOptions& options, F&& f) {
  return withSceneAlone(desc, eyeRayGrid(width, height, options), options, options.hierarchy,
                        [&](const auto& scene) {
                          using T = typename std::decay_t<decltype(scene)>::Real;
                          const Camera<T> camera(desc.camera, width, height);
                          return f(scene, camera);
                        });
}

}  // namespace rt
