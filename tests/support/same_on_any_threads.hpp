// Test support: a picture rendered on 1 and on 3 threads is the same, and Tracer::pixel() gives each pixel.
#pragma once

#include <catch2/catch.hpp>

#include "raytrace/render/renderer.hpp"
#include "raytrace/render/scene_setup.hpp"
#include "raytrace/render/tracer.hpp"
#include "raytrace/scene/arithmetic.hpp"

namespace rt::test {

// Checks every pixel; returns the eye rays pixel() traced for the whole picture.
inline size_t checkSameOnAnyThreads(const SceneDesc& scene, int width, int height, RenderOptions options) {
  options.threads = 1;
  const Image one = render(scene, width, height, options);
  options.threads = 3;
  const Image three = render(scene, width, height, options);
  const Arithmetic arithmetic = chooseArithmetic(scene, options.arithmetic);
  return withPrecision(arithmetic.tier, [&](auto tag) {
    using T = decltype(tag);
    const Scene<T> s(scene, arithmetic);
    const Camera<T> camera(scene.camera, width, height);
    Tracer<T> tracer(s, options);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        CAPTURE(x, y);
        REQUIRE(one.at(x, y) == three.at(x, y));
        REQUIRE(one.at(x, y) == tracer.pixel(camera, x, y));
      }
    }
    return size_t(tracer.counts().eye);
  });
}

}  // namespace rt::test
