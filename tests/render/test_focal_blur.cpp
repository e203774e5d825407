// POV-Ray's focal blur: the camera statement's items, the lens rays (analytic), and the same picture on any
// threads with the adaptive test's sample counts.
#include <catch2/catch.hpp>

#include "raytrace/parse/povray/scene_builder.hpp"
#include "raytrace/render/renderer.hpp"
#include "raytrace/render/tracer.hpp"
#include "raytrace/scene/arithmetic.hpp"
#include "same_on_any_threads.hpp"

using namespace rt;

namespace {

SceneDesc pov(const std::string& camera) {
  const std::string text = "#version 3.7;\n" + camera +
      "light_source { <2, 6, -2> rgb 1 }\n"
      "sphere { <0, 0.7, 0>, 0.7 pigment { rgb <1, 0.5, 0.2> } }\n"
      "sphere { <1.5, 0.5, 3>, 0.5 pigment { rgb <0.2, 0.5, 1> } }\n"
      "plane { y, 0 pigment { checker rgb 1 rgb 0.2 } }\n";
  return rt::povray::parsePovRay(text, "blur.pov", rt::povray::PovRayOptions{{}, 24, 18, false});
}

}  // namespace

TEST_CASE("focal blur: the camera's aperture, blur_samples, focal_point, confidence and variance", "[render]") {
  const SceneDesc both = pov("camera { location <0, 3, -4> look_at 0 aperture 0.5 blur_samples 3, 50 "
                             "focal_point <0, 1, 0> confidence 0.95 variance 1/1000 translate x }\n");
  const CameraDesc::FocalBlur& b = both.camera.focalBlur;
  CHECK(b.aperture == 0.5);
  CHECK(b.minSamples == 3);
  CHECK(b.maxSamples == 50);
  CHECK(b.focalPoint == glm::dvec3(1, 1, 0));  // moved with the camera
  CHECK(b.confidence == 0.95);
  CHECK(b.variance == 1.0 / 1000);
  // POV-Ray's defaults: at least 4 samples below 7, else 7; confidence 0.9, variance 1/128.
  const SceneDesc most = pov("camera { location <0, 3, -4> look_at 0 aperture 0.5 blur_samples 20 }\n");
  CHECK(most.camera.focalBlur.minSamples == 0);
  CHECK(most.camera.focalBlur.confidence == 0.9);
  CHECK(most.camera.focalBlur.variance == 1.0 / 128);
  CHECK(Camera<double>(most.camera, 24, 18).focalBlur().minSamples == 7);
  const SceneDesc few = pov("camera { location <0, 3, -4> look_at 0 aperture 0.5 blur_samples 5 }\n");
  CHECK(Camera<double>(few.camera, 24, 18).focalBlur().minSamples == 4);
  const SceneDesc sharp = pov("camera { location <0, 3, -4> look_at 0 blur_samples 5 }\n");
  CHECK_FALSE(Camera<double>(sharp.camera, 24, 18).blurred());
}

TEMPLATE_TEST_CASE("focal blur: every lens ray meets the pinhole ray on the plane of focus", "", float, double) {
  using T = TestType;
  CameraDesc c;
  c.location = {0, 0, 0};
  c.lookAt = {0, 0, 1};
  c.right = {4.0 / 3, 0, 0};
  c.focalBlur.aperture = 2;
  c.focalBlur.maxSamples = 10;
  c.focalBlur.focalPoint = {3, -2, 10};  // the plane z = 10
  const Camera<T> cam(c, 16, 12);
  const Ray<T> pinhole = cam.pixelRay(3, 4);
  const T t = T(10) / pinhole.dir.z;
  const Vec3<T> focus = pinhole.origin + t * pinhole.dir;
  for (const glm::vec2 lens : {glm::vec2(0, 0), glm::vec2(0.5f, 0.25f), glm::vec2(0.999f, 0.7f)}) {
    CAPTURE(lens.x, lens.y);
    const Ray<T> ray = cam.throughLens(pinhole, lens);
    // From the lens's disc of radius aperture/4 = 0.5 in the plane of right and up, at √u of it.
    CHECK(double(ray.origin.z) == Approx(0).margin(1e-6));
    CHECK(double(glm::length(ray.origin)) == Approx(0.5 * std::sqrt(lens.x)).margin(1e-6));
    const T s = (focus.z - ray.origin.z) / ray.dir.z;
    const Vec3<T> met = ray.origin + s * ray.dir;
    CHECK(double(met.x) == Approx(double(focus.x)).margin(1e-5));
    CHECK(double(met.y) == Approx(double(focus.y)).margin(1e-5));
  }
}

TEST_CASE("focal blur: the same picture on any threads, pixel() agrees, and variance 0 takes every sample",
          "[render]") {
  const SceneDesc scene = pov("camera { location <0, 3, -4> look_at 0 aperture 0.8 blur_samples 4, 9 "
                              "focal_point <0, 0.7, 0> variance 0 }\n");
  CHECK(test::checkSameOnAnyThreads(scene, 24, 18, RenderOptions{}) == 24 * 18 * 9);
}
