#include "raytrace/render.hpp"

#include "raytrace/tracer.hpp"

namespace rt {

Image render(const SceneDesc& desc, int width, int height, const RenderOptions& options) {
  const Arithmetic arithmetic = chooseArithmetic(desc, options.arithmetic);
  Image image(width, height);
  withPrecision(arithmetic.precision, [&](auto tag) {
    using T = decltype(tag);
    const Scene<T> scene(desc, arithmetic);
    const Camera<T> camera(desc.camera, width, height);
    const Tracer<T> tracer(scene, options);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) image.at(x, y) = tracer.pixel(camera, x, y);
    }
  });
  return image;
}

}  // namespace rt
