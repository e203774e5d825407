// What a command receives once its arguments are checked and its scene is loaded, and the helpers the
// command families share.
#pragma once

#include <ostream>

#include "raytrace/accel/scene.hpp"
#include "raytrace/render/camera.hpp"
#include "raytrace/render/renderer.hpp"
#include "raytrace/scene/arithmetic.hpp"
#include "raytrace/scene/description.hpp"

namespace rt {

struct Invocation {
  SceneDesc scene;
  int width = 0, height = 0, x = 0, y = 0;
  RenderOptions options;
  std::ostream* progress = nullptr;  // where render shows its progress line (not with --quiet)
  std::ostream* stats = nullptr;     // --stats: where render reports how long each step took
  double loadSeconds = 0;         // the reading of the scene file

  // The eye rays' grid the arithmetic is chosen for; commands without an image size get the default view.
  View view() const { return width > 0 && height > 0 ? View{width, height} : View{}; }
};

// Runs f(scene, camera) at the precision the scene needs.
template <class F> auto withScene(const Invocation& inv, F&& f) {
  const Arithmetic arithmetic = chooseArithmetic(inv.scene, inv.options.arithmetic, inv.view());
  return withPrecision(arithmetic.tier, [&](auto tag) {
    using T = decltype(tag);
    const Scene<T> scene(inv.scene, arithmetic, inv.options.hierarchy, inv.options.threads);
    const Camera<T> camera(inv.scene.camera, inv.width, inv.height);
    return f(scene, camera);
  });
}

// The image commands (image_commands.cpp).
int raycast(const Invocation& inv, std::ostream& out);
int renderImage(const Invocation& inv, std::ostream& out);

// The commands that print what the renderer sees (inspect.cpp).
int sceneinfo(const Invocation& inv, std::ostream& out);
int pixelray(const Invocation& inv, std::ostream& out);
int firsthit(const Invocation& inv, std::ostream& out);
int pixelcolor(const Invocation& inv, std::ostream& out);
int printrays(const Invocation& inv, std::ostream& out);
int pixeltrace(const Invocation& inv, std::ostream& out);
int printbvh(const Invocation& inv, std::ostream& out);

}  // namespace rt
